#include "run/stability.hpp"

#include <algorithm>
#include <cmath>
#include <mutex>

#include "course/course_backend.hpp"
#include "metrics/stability_theory.hpp"
#include "run/accuracy_run.hpp"
#include "run/divergence.hpp"
#include "run/parallel.hpp"
#include "scene/backend_names.hpp"
#include "scene/motion.hpp"

namespace bb {

StabilityTrial try_step(const Backend& backend, const Scene& scene, double dt) {
  try {
    const auto sim = backend.start(scene, dt);
    const DivergenceBounds bounds = divergence_bounds(scene);
    State state(scene.bodies.size());
    sim->read(state);
    const double e0 = total_energy(scene, state);
    const double allowed_gain =
        (scene.stability.energy_factor - 1.0) * std::max(std::abs(e0), bounds.energy_scale);
    const long steps = static_cast<long>(std::ceil(scene.duration / dt - 1e-9));
    for (long n = 1; n <= steps; ++n) {
      sim->step();
      sim->read(state);
      if (auto why = divergence(scene, bounds, state, e0)) return {false, *why};
      if (total_energy(scene, state) - e0 > allowed_gain)
        return {false, "energy rose above " + std::to_string(scene.stability.energy_factor) +
                           " times its scale"};
    }
    return {true, ""};
  } catch (const std::exception& e) {
    return {false, std::string("error: ") + e.what()};
  }
}

StabilityResult find_stability(const Backend& backend, const Scene& scene) {
  StabilityResult r;
  r.backend = backend.name();
  if (const std::string missing = missing_features(backend, scene); !missing.empty()) {
    r.status = "unsupported";
    r.reason = "does not support: " + missing;
    return r;
  }
  double lo = scene.stability.dt_min, hi = scene.stability.dt_max;
  const auto trial = [&](double dt) {
    ++r.trials;
    return try_step(backend, scene, dt);
  };
  if (const StabilityTrial top = trial(hi); top.stable) {
    r.status = "stable at every dt tried";
    r.critical_dt = hi;
    return r;
  } else {
    r.reason = top.reason;
  }
  if (const StabilityTrial bottom = trial(lo); !bottom.stable) {
    r.status = "unstable at every dt tried";
    r.unstable_dt = lo;
    r.reason = bottom.reason;
    return r;
  }
  // Invariant: lo is stable, hi is not. Halve the bracket in log dt.
  while (hi / lo > 1.001 && r.trials < 40) {
    const double mid = std::sqrt(lo * hi);
    if (const StabilityTrial t = trial(mid); t.stable) {
      lo = mid;
    } else {
      hi = mid;
      r.reason = t.reason;
    }
  }
  r.status = "bracketed";
  r.critical_dt = lo;
  r.unstable_dt = hi;
  return r;
}

std::vector<StabilityResult> find_stability_all(
    const Scene& scene, const Registry& registry, const std::vector<std::string>& backends,
    int jobs, const std::function<void(const std::string&)>& on_done) {
  const BackendSet set = backends_for(scene, registry);
  std::vector<const Backend*> chosen;
  for (const Backend* b : set.all)
    if (backends.empty() ||
        std::find(backends.begin(), backends.end(), b->name()) != backends.end())
      chosen.push_back(b);
  std::vector<StabilityResult> out(chosen.size());
  std::mutex report;
  parallel_for(static_cast<int>(chosen.size()), jobs, [&](int i) {
    out[i] = find_stability(*chosen[i], scene);
    for (const CourseVariant& v : course_variants(scene))
      if (v.name == chosen[i]->name())
        if (auto limit = theoretical_limit(scene, v.integrator)) {
          out[i].theory = limit->dt;
          out[i].theory_formula = limit->formula;
        }
    if (on_done) {
      const std::lock_guard<std::mutex> lock(report);
      on_done(chosen[i]->name());
    }
  });
  return out;
}

}  // namespace bb
