#include "run/stability.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "course/course_backend.hpp"
#include "course/stability_theory.hpp"
#include "metrics/energy_growth.hpp"
#include "model/text.hpp"
#include "run/accuracy_run.hpp"
#include "run/case_runner.hpp"
#include "run/engine_interventions.hpp"
#include "run/stability_chains.hpp"
#include "run/stability_watch.hpp"
#include "run/wire.hpp"
#include "study/backend_names.hpp"
#include "study/case_error.hpp"
#include "study/case_limits.hpp"
#include "study/start_case.hpp"

namespace bb {

namespace {

/// Why a trial at `dt` would pass the cap of steps every run keeps to, or "".
std::string beyond_step_cap(const Scene& scene, double dt) {
  const double steps = std::ceil(scene.duration / dt - 1e-9);
  if (steps <= kMaxStepsPerRun) return "";
  std::ostringstream m;
  m << "not run: dt " << dt << " s over the " << scene.duration << " s duration is " << steps
    << " steps, more than the " << kMaxStepsPerRun << " a run may take";
  return m.str();
}

}  // namespace

StabilityTrial try_step(const Backend& backend, const Scene& scene, double dt, long steps) {
  if (std::string why = beyond_step_cap(scene, dt); !why.empty()) return {false, why, "not run"};
  if (steps == 0) steps = StabilityWatch::trial_steps(scene, dt);
  try {
    const auto sim = start_case(backend, scene, dt);
    State state(scene.bodies.size());
    sim->read(state);
    StabilityWatch watch(scene, dt, state, steps);
    // The step loop is timed whole (read like cost), for the report's floor.
    const auto loop_start = std::chrono::steady_clock::now();
    const auto timed = [&](StabilityTrial trial) {
      trial.step_seconds =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - loop_start).count();
      return trial;
    };
    for (long n = 1; n <= watch.steps(); ++n) {
      sim->step();
      // An engine that reset itself or held a body at its cap has its verdict already.
      if (auto intervened = intervened_trial(sim->interventions(), dt)) return timed(*intervened);
      sim->read(state);
      if (!watch.observe(n, state)) break;
    }
    return timed(*watch.verdict());
  } catch (const std::exception& e) {
    return {false, std::string("error: ") + e.what(), "failed"};
  }
}

StabilityTrial judge_step(const Backend& backend, const Scene& scene, double dt,
                          std::optional<double> theory) {
  StabilityTrial trial = try_step(backend, scene, dt);
  const long steps = StabilityWatch::trial_steps(scene, dt);
  const double longer = static_cast<double>(steps) * static_cast<double>(kTheoryProbeFactor);
  if (!trial.stable || !theory || dt <= *theory || longer > kMaxStepsPerRun) return trial;
  StabilityTrial probe = try_step(backend, scene, dt, steps * kTheoryProbeFactor);
  probe.step_seconds += trial.step_seconds;
  const std::string why = "the step is past the theory's limit of " +
                          significant_digits(*theory, 3) + " s, so it was run " +
                          std::to_string(kTheoryProbeFactor) + " times longer than the usual " +
                          std::to_string(steps) + " steps";
  probe.reason = probe.stable ? "stable over a longer run (" + why + ")" +
                                    (probe.reason.empty() ? "" : ": " + probe.reason)
                              : probe.reason + " (seen because " + why + ")";
  return probe;
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

namespace {

/// The theory, where the scene allows one, beside a course variant's result.
void add_theory(const Scene& scene, StabilityResult& r) {
  for (const CourseVariant& v : course_variants(scene))
    if (v.name == r.backend)
      if (auto limit = theoretical_limit(scene, v.integrator)) {
        r.theory = limit->dt;
        r.theory_formula = limit->formula;
        r.theory_note = limit->note;
      }
}

/// The search's smallest step must keep its trials within the cap (the loader sees to it for
/// every case it loads); a scene built otherwise is refused before any trial.
void require_search_within_cap(const Scene& scene) {
  if (std::string why = beyond_step_cap(scene, scene.stability.dt_min); !why.empty())
    throw CaseError(scene.file, 0, "the stability search's dt_min is too small: " + why);
}

}  // namespace

std::optional<double> theory_for(const Scene& scene, const std::string& backend) {
  for (const CourseVariant& v : course_variants(scene))
    if (v.name == backend)
      if (auto limit = theoretical_limit(scene, v.integrator)) return limit->dt;
  return std::nullopt;
}

StabilityResult find_stability(const Backend& backend, const Scene& scene) {
  require_search_within_cap(scene);
  if (auto r = unsupported(backend, scene)) return *r;
  StabilitySearch search(scene.stability.dt_min, scene.stability.dt_max);
  const std::optional<double> theory = theory_for(scene, backend.name());
  while (auto dt = search.next()) search.record(*dt, judge_step(backend, scene, *dt, theory));
  StabilityResult r;
  r.backend = backend.name();
  search.fill(r);
  add_theory(scene, r);
  return r;
}

KnownTrials known_trials(const std::vector<RunRecord>& runs) {
  KnownTrials out;
  for (const RunRecord& run : runs)
    if (run.dt && run.stability_trial) out[{run.backend, *run.dt}] = *run.stability_trial;
  return out;
}

std::vector<StabilityResult> find_stability_all(
    const Scene& scene, const Registry& registry, const std::vector<std::string>& backends,
    int jobs, const std::function<void(const std::string&)>& on_done, bool isolation,
    double timeout, const KnownTrials& known, RunCache* cache) {
  require_search_within_cap(scene);
  const BackendSet set = backends_for(scene, registry);
  std::vector<const Backend*> chosen;
  for (const Backend* b : set.all)
    if (backends.empty() ||
        std::find(backends.begin(), backends.end(), b->name()) != backends.end())
      chosen.push_back(b);
  std::vector<StabilityResult> out(chosen.size());
  // The backends that can be searched are searched together; the others say why not.
  std::vector<const Backend*> searched;
  std::vector<std::size_t> at;
  for (std::size_t i = 0; i < chosen.size(); ++i) {
    if (auto r = unsupported(*chosen[i], scene)) {
      out[i] = *r;
      if (on_done) on_done(chosen[i]->name());
      continue;
    }
    searched.push_back(chosen[i]);
    at.push_back(i);
  }
  std::vector<StabilityResult> found =
      StabilityChains(scene, searched, {jobs, isolation, timeout, &known, cache, on_done}).run();
  for (std::size_t k = 0; k < found.size(); ++k) out[at[k]] = std::move(found[k]);
  for (StabilityResult& r : out) add_theory(scene, r);
  return out;
}

}  // namespace bb
