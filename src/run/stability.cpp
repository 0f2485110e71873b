#include "run/stability.hpp"

#include <algorithm>
#include <cmath>

#include "course/course_backend.hpp"
#include "metrics/stability_theory.hpp"
#include "run/accuracy_run.hpp"
#include "run/case_runner.hpp"
#include "run/child_pool.hpp"
#include "run/divergence.hpp"
#include "run/wire.hpp"
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
      const double energy = total_energy(scene, state);
      if (auto why = divergence(scene, bounds, state, e0, energy)) return {false, *why};
      if (energy - e0 > allowed_gain)
        return {false, "energy rose above " + std::to_string(scene.stability.energy_factor) +
                           " times its scale"};
    }
    return {true, ""};
  } catch (const std::exception& e) {
    return {false, std::string("error: ") + e.what()};
  }
}

std::optional<double> Bisection::next() const {
  switch (phase_) {
    case Phase::Top:
      return hi_;
    case Phase::Bottom:
      return lo_;
    case Phase::Halving:
      return std::sqrt(lo_ * hi_);
    case Phase::Done:
      return std::nullopt;
  }
  return std::nullopt;
}

void Bisection::record(double dt, const StabilityTrial& trial) {
  ++trials_;
  if (!trial.stable) reason_ = trial.reason;
  if (phase_ == Phase::Top) {
    phase_ = trial.stable ? Phase::Done : Phase::Bottom;
    if (trial.stable) status_ = "stable at every dt tried";
    return;
  }
  if (phase_ == Phase::Bottom) {
    phase_ = trial.stable ? Phase::Halving : Phase::Done;
    if (!trial.stable) status_ = "unstable at every dt tried";
  } else {
    // Invariant: lo is stable, hi is not.
    (trial.stable ? lo_ : hi_) = dt;
  }
  if (phase_ == Phase::Halving && (hi_ / lo_ <= 1.001 || trials_ >= 40)) {
    phase_ = Phase::Done;
    status_ = "bracketed";
  }
}

void Bisection::fill(StabilityResult& r) const {
  r.status = status_;
  r.reason = reason_;
  r.trials = trials_;
  if (status_ == "stable at every dt tried") r.critical_dt = hi_;
  if (status_ == "unstable at every dt tried") r.unstable_dt = lo_;
  if (status_ == "bracketed") r.critical_dt = lo_, r.unstable_dt = hi_;
}

namespace {

/// A result that says why the backend cannot be searched, or nullopt when it can.
std::optional<StabilityResult> unsupported(const Backend& backend, const Scene& scene) {
  const std::string missing = missing_features(backend, scene);
  if (missing.empty()) return std::nullopt;
  StabilityResult r;
  r.backend = backend.name();
  r.status = "unsupported";
  r.reason = "does not support: " + missing;
  return r;
}

}  // namespace

StabilityResult find_stability(const Backend& backend, const Scene& scene) {
  if (auto r = unsupported(backend, scene)) return *r;
  Bisection search(scene.stability.dt_min, scene.stability.dt_max);
  while (auto dt = search.next()) search.record(*dt, try_step(backend, scene, *dt));
  StabilityResult r;
  r.backend = backend.name();
  search.fill(r);
  return r;
}

std::vector<StabilityResult> find_stability_all(
    const Scene& scene, const Registry& registry, const std::vector<std::string>& backends,
    int jobs, const std::function<void(const std::string&)>& on_done, bool isolation,
    double timeout) {
  const BackendSet set = backends_for(scene, registry);
  std::vector<const Backend*> chosen;
  for (const Backend* b : set.all)
    if (backends.empty() ||
        std::find(backends.begin(), backends.end(), b->name()) != backends.end())
      chosen.push_back(b);
  std::vector<StabilityResult> out(chosen.size());
  std::vector<Bisection> searches(chosen.size(),
                                  Bisection(scene.stability.dt_min, scene.stability.dt_max));
  ChildPool pool(jobs, isolation);
  // Each finished trial queues the backend's next one until its search is over.
  std::function<void(std::size_t)> queue_next = [&](std::size_t i) {
    const Backend& b = *chosen[i];
    if (const auto dt = searches[i].next()) {
      const double step = *dt;
      pool.submit(
          b.name() + " stability at dt " + std::to_string(step),
          [&b, &scene, step] { return wire::encode(try_step(b, scene, step)); },
          time_limit(scene, step, timeout),
          [&, i, step](const ChildOutcome& o) {
            searches[i].record(step, o.kind == ChildOutcome::Kind::Done
                                         ? wire::decode_trial(o.payload)
                                         : StabilityTrial{false, o.reason});
            queue_next(i);
          });
      return;
    }
    out[i].backend = b.name();
    searches[i].fill(out[i]);
    if (on_done) on_done(b.name());
  };
  for (std::size_t i = 0; i < chosen.size(); ++i) {
    if (auto r = unsupported(*chosen[i], scene)) {
      out[i] = *r;
      if (on_done) on_done(chosen[i]->name());
      continue;
    }
    queue_next(i);
  }
  pool.run();
  // Theory, where the scene allows one, beside each course variant.
  for (std::size_t i = 0; i < chosen.size(); ++i)
    for (const CourseVariant& v : course_variants(scene))
      if (v.name == chosen[i]->name())
        if (auto limit = theoretical_limit(scene, v.integrator)) {
          out[i].theory = limit->dt;
          out[i].theory_formula = limit->formula;
        }
  return out;
}

}  // namespace bb
