#include "run/accuracy_run.hpp"

#include <chrono>
#include <new>

#include "observe/step_observer.hpp"
#include "physics/energy.hpp"
#include "run/divergence.hpp"
#include "run/engine_interventions.hpp"
#include "run/stability_watch.hpp"
#include "run/trajectory_writer.hpp"
#include "study/start_case.hpp"

namespace bb {

std::string missing_features(const Backend& backend, const Scene& scene) {
  std::string out;
  for (Feature f : scene.features().missing_from(backend.supports())) {
    const std::string note = feature_absence_note(f);
    out += (out.empty() ? "" : ", ") + feature_name(f) + (note.empty() ? "" : " (" + note + ")");
  }
  return out;
}

namespace {

/// Everything that reads a run's state at every step, not only at its samples: the
/// observer (contacts, apexes, turns), the stability trial the run judges on its own steps,
/// and the trajectory file (run --trajectories).
struct StepWatchers {
  StepObserver observer;
  std::optional<StabilityWatch> trial;
  TrajectoryWriter* steps = nullptr;
  /// Whether any of them reads the state at every step (else the loop reads none).
  bool any() const { return observer.active() || trial || steps; }
};

/// The stability trial a run judges on its own steps: with `judge`, at a step the search
/// begins with (its dt_min or dt_max), where the trial takes exactly the run's `run_steps`.
void watch_trial(const Scene& scene, double dt, bool judge, long run_steps, const State& start,
                 StepWatchers& watchers) {
  if (judge && (dt == scene.stability.dt_min || dt == scene.stability.dt_max) &&
      StabilityWatch::trial_steps(scene, dt) == run_steps)
    watchers.trial.emplace(scene, dt, start, StabilityWatch::trial_steps(scene, dt));
}

/// The steps from one sample to the next, each step's state handed to the watchers; the
/// record counts them.
void step_to_next_sample(Simulation& sim, double dt, int per_sample, State& state,
                         StepWatchers& watchers, RunRecord& record) {
  // The block of steps to the next sample is timed (read like cost: two clock reads).
  const auto block_start = std::chrono::steady_clock::now();
  for (int k = 1; k <= per_sample; ++k) {
    sim.step();
    if (!watchers.any()) continue;
    sim.read(state);
    if (watchers.trial) watchers.trial->observe(record.steps + k, state);
    const double t_step = static_cast<double>(record.steps + k) * dt;
    if (watchers.observer.active()) watchers.observer.observe(t_step, state);
    if (watchers.steps) watchers.steps->write(t_step, state);
  }
  record.step_seconds +=
      std::chrono::duration<double>(std::chrono::steady_clock::now() - block_start).count();
  record.steps += per_sample;
}

/// Whether the run stops at the sample just taken at time `t`: its engine threw its state
/// away (its own warning), or it diverged. The record says why and when.
bool stops_at_sample(const Simulation& sim, const Scene& scene, double dt, double t,
                     const DivergenceBounds& bounds, const State& state, double initial_energy,
                     EnergyMeter& energy, RunRecord& record) {
  if (const auto reset = intervention_of(sim.interventions(), EngineIntervention::Kind::Reset)) {
    record.status = RunStatus::Diverged;
    record.reason = intervention_reason(*reset, dt);
    record.diverged_at = intervention_time(*reset, dt);
    return true;
  }
  if (auto why = divergence(scene, bounds, state, initial_energy, energy(state))) {
    record.status = RunStatus::Diverged;
    record.reason = *why;
    record.diverged_at = t;
    return true;
  }
  return false;
}

/// What the run's end says: a cap its engine held it at, the trial's verdict, an adaptive
/// solver's own steps, the settings as they stood and the events.
void finish_run(const Simulation& sim, double dt, const StepWatchers& watchers, RunRecord& record) {
  // A run its engine held at a cap of its own ran to the end, and says so.
  const std::vector<EngineIntervention> interventions = sim.interventions();
  const auto cap = intervention_of(interventions, EngineIntervention::Kind::Cap);
  if (cap && record.status == RunStatus::Ok) {
    record.status = RunStatus::Capped;
    record.reason = intervention_reason(*cap, dt);
  }
  if (watchers.trial) {
    const auto intervened = intervened_trial(interventions, dt);
    record.stability_trial = intervened ? intervened : watchers.trial->verdict();
  }
  if (auto internal = sim.internal_steps()) record.steps = *internal;
  // Settings as they stood at the end: the reference names a change of method there.
  record.engine_settings = sim.settings();
  const StepObserver& observer = watchers.observer;
  record.trajectory.events = sim.exact_events().value_or(observer.trace());
  // Whether a body's whole turns could be counted comes from the reference's samples
  // (its events themselves are located exactly; its peaks between its own steps).
  if (observer.active() && sim.exact_events()) {
    EventTrace& events = record.trajectory.events;
    const EventTrace& seen = observer.trace();
    for (std::size_t i = 0; i < events.bodies.size(); ++i)
      events.bodies[i].turn_unclear = seen.bodies[i].turn_unclear;
  }
}

/// The run itself, from its start to its end or divergence, sampled into the record.
void run_steps(const Backend& backend, const Scene& scene, double dt, bool judge_stability,
               TrajectoryWriter* steps, RunRecord& record) {
  const auto sim = start_case(backend, scene, dt);
  record.engine_settings = sim->settings();
  const int per_sample = scene.steps_per_sample(dt);
  const int samples = scene.sample_count();
  const DivergenceBounds bounds = divergence_bounds(scene);
  EnergyMeter energy(scene);
  State state(scene.bodies.size());
  sim->read(state);
  const double initial_energy = energy(state);
  // Contacts, apexes and turns are watched at every step, not only at the samples.
  StepWatchers watchers{StepObserver(scene), std::nullopt, steps};
  watchers.observer.observe(0.0, state);
  // At a step the stability search begins with, its trial is judged on these steps too.
  watch_trial(scene, dt, judge_stability,
              static_cast<long>(per_sample) * static_cast<long>(samples), state, watchers);
  watchers.observer.write_turns(state);
  if (steps) steps->write(0.0, state);
  record.trajectory.times.push_back(0.0);
  record.trajectory.states.push_back(state);
  for (int j = 1; j <= samples; ++j) {
    step_to_next_sample(*sim, dt, per_sample, state, watchers, record);
    sim->read(state);
    watchers.observer.write_turns(state);
    // Simulated time is a step count times dt, never a running sum.
    const double t = static_cast<double>(record.steps) * dt;
    record.trajectory.times.push_back(t);
    record.trajectory.states.push_back(state);
    // A crash from here on keeps the rows up to this sample.
    if (steps) steps->flush();
    if (stops_at_sample(*sim, scene, dt, t, bounds, state, initial_energy, energy, record)) break;
  }
  finish_run(*sim, dt, watchers, record);
}

}  // namespace

RunRecord run_accuracy(const Backend& backend, const Scene& scene, double dt, bool judge_stability,
                       TrajectoryWriter* steps) {
  RunRecord record;
  record.backend = backend.name();
  record.dt = dt;
  if (const std::string missing = missing_features(backend, scene); !missing.empty()) {
    record.status = RunStatus::Unsupported;
    record.reason = "does not support: " + missing;
    return record;
  }
  try {
    run_steps(backend, scene, dt, judge_stability, steps, record);
  } catch (const UnsupportedScene& e) {
    // A scene past what the backend answers (the reference's exact answer) is unsupported,
    // with the reason.
    record.status = RunStatus::Unsupported;
    record.reason = e.what();
  } catch (const std::bad_alloc&) {
    record.status = RunStatus::Crashed;
    record.reason = "out of memory";
  } catch (const std::exception& e) {
    record.status = RunStatus::Error;
    record.reason = e.what();
  }
  return record;
}

}  // namespace bb
