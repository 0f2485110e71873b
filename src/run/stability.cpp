#include "run/stability.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "course/course_backend.hpp"
#include "course/stability_theory.hpp"
#include "metrics/energy_growth.hpp"
#include "run/accuracy_run.hpp"
#include "run/case_runner.hpp"
#include "run/child_pool.hpp"
#include "run/engine_interventions.hpp"
#include "run/stability_watch.hpp"
#include "run/wire.hpp"
#include "scene/backend_names.hpp"
#include "scene/case_error.hpp"
#include "scene/case_limits.hpp"
#include "scene/text.hpp"

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
    const auto sim = backend.start(scene, dt);
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

std::optional<double> theory_for(const Scene& scene, const std::string& backend) {
  for (const CourseVariant& v : course_variants(scene))
    if (v.name == backend)
      if (auto limit = theoretical_limit(scene, v.integrator)) return limit->dt;
  return std::nullopt;
}

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

/// Seconds a trial of `scene` at `dt` may take in its child: as a run's limit, for every
/// step it may take (the usual trial and, past the theory's limit, the longer one).
double trial_time_limit(const Scene& scene, double dt, double timeout, bool longer) {
  if (timeout > 0.0) return timeout;
  const double steps = static_cast<double>(StabilityWatch::trial_steps(scene, dt)) *
                       (longer ? 1.0 + static_cast<double>(kTheoryProbeFactor) : 1.0);
  return steps_time_limit(scene, steps);
}

/// The search's smallest step must keep its trials within the cap (the loader sees to it for
/// every case it loads); a scene built otherwise is refused before any trial.
void require_search_within_cap(const Scene& scene) {
  if (std::string why = beyond_step_cap(scene, scene.stability.dt_min); !why.empty())
    throw CaseError(scene.file, 0, "the stability search's dt_min is too small: " + why);
}

}  // namespace

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
  std::vector<StabilitySearch> searches(
      chosen.size(), StabilitySearch(scene.stability.dt_min, scene.stability.dt_max));
  std::vector<std::optional<double>> theories;
  for (const Backend* b : chosen) theories.push_back(theory_for(scene, b->name()));
  ChildPool pool(jobs, isolation);
  // Each finished trial queues the backend's next one until its search is over.
  std::function<void(std::size_t)> queue_next = [&](std::size_t i) {
    const Backend& b = *chosen[i];
    if (const auto dt = searches[i].next()) {
      const double step = *dt;
      const std::optional<double> theory = theories[i];
      // A trial an accuracy run already judged on its own steps is not run again (unless it
      // is stable past the theory's limit: judge_step() then runs a longer one).
      if (const auto found = known.find({b.name(), step});
          found != known.end() && (!found->second.stable || !theory || step <= *theory)) {
        searches[i].record(step, found->second);
        queue_next(i);
        return;
      }
      const std::string key = cache ? cache->key(scene, "stability trial", b, step) : "";
      if (const auto kept = cache ? cache->find(key) : std::nullopt) {
        searches[i].record(step, wire::decode_trial(*kept));
        queue_next(i);
        return;
      }
      pool.submit(
          b.name() + " stability at dt " + std::to_string(step),
          [&b, &scene, step, theory] { return wire::encode(judge_step(b, scene, step, theory)); },
          trial_time_limit(scene, step, timeout, theory && step > *theory),
          [&, i, step, key](const ChildOutcome& o) {
            const StabilityTrial trial = o.kind == ChildOutcome::Kind::Done
                                             ? wire::decode_trial(o.payload)
                                             : StabilityTrial{false, o.reason, "failed"};
            // A trial that did not finish (a crash, a timeout) is tried again next time.
            if (!key.empty())
              cache->keep(key, o.kind == ChildOutcome::Kind::Done ? o.payload : wire::encode(trial),
                          trial.growth != "failed");
            out[i].step_seconds += trial.step_seconds;
            searches[i].record(step, trial);
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
  for (StabilityResult& r : out) add_theory(scene, r);
  return out;
}

}  // namespace bb
