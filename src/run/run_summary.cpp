#include "run/run_summary.hpp"

#include <algorithm>

#include "metrics/order.hpp"
#include "physics/energy.hpp"
#include "run/divergence.hpp"
#include "run/drawn_bodies.hpp"
#include "study/backend_names.hpp"

namespace bb {

namespace {

std::optional<double> measured_value(const RunRecord& run, const std::string& name) {
  for (const ObservableResult& o : run.observables)
    if (o.name == name) return o.measured.value;
  return std::nullopt;
}

}  // namespace

void add_observables(const Scene& scene, RunRecord& run, const RunRecord& against) {
  for (const Observe& o : scene.observes) {
    ObservableResult r{o.name, {}, std::nullopt};
    // A capped run ran to the end: its values are shown (its status says whose they are).
    if (ran_to_end(run.status))
      r.measured = measure(scene, o, run.trajectory, &against.trajectory.events);
    else
      r.measured.note = "run " + status_name(run.status);
    // A kind with a formula (terminal_velocity) is compared with the formula's value; a
    // run already measured in its child has its own value, not its states, to give.
    if (const auto formula = formula_value(scene, o))
      r.reference = formula;
    else if (&against == &run && run.backend != kReferenceName)
      r.reference = std::nullopt;
    else if (against.status == RunStatus::Ok && against.summarised)
      r.reference = measured_value(against, o.name);
    else if (against.status == RunStatus::Ok)
      r.reference = measure(scene, o, against.trajectory, &against.trajectory.events).value;
    run.observables.push_back(r);
  }
}

void add_series(const Scene& scene, RunRecord& run, const Trajectory* reference) {
  const Trajectory& t = run.trajectory;
  run.energy.clear();
  run.distance.clear();
  EnergyMeter energy(scene);
  for (const State& s : t.states) run.energy.push_back(energy(s));
  if (reference == nullptr || reference->states.empty()) return;
  for (std::size_t j = 0; j < t.states.size() && j < reference->states.size(); ++j) {
    double worst = 0.0;
    for (std::size_t b = 0; b < t.states[j].size(); ++b)
      worst = std::max(worst, (t.states[j][b].position - reference->states[j][b].position).norm());
    run.distance.push_back(worst);
  }
}

void keep_drawn_states(const Scene& scene, RunRecord& run) {
  const std::vector<int> drawn = drawn_bodies(scene);
  for (State& s : run.trajectory.states) {
    if (s.size() != scene.bodies.size()) continue;  // already cut
    State kept;
    kept.reserve(drawn.size());
    for (int b : drawn) kept.push_back(s[b]);
    s = std::move(kept);
  }
}

void keep_plotted_states(const Scene& scene, RunRecord& run) {
  std::vector<State>& states = run.trajectory.states;
  if (!run.dt || *run.dt != scene.report_dt) {
    states.clear();
    states.shrink_to_fit();
    return;
  }
  keep_drawn_states(scene, run);
}

void record_position_scale(RunRecord& run) {
  run.position_scale = largest_position(run.trajectory);
  run.travel = largest_travel(run.trajectory);
}

void summarise_in_child(const Scene& scene, RunRecord& run, const RunRecord& against) {
  // A body far outside everywhere the reference's bodies go has blown up (divergence.hpp).
  if (run.status == RunStatus::Ok && &against != &run && against.backend == kReferenceName)
    if (auto beyond = beyond_reference(scene, run.trajectory, against.trajectory)) {
      run.status = RunStatus::Diverged;
      run.reason = beyond->reason;
      run.diverged_at = beyond->time;
    }
  // A run measured against itself (the fallback's finest) has no errors.
  if (ran_to_end(run.status) && &against != &run)
    run.errors = compare(scene, run.trajectory, against.trajectory);
  add_observables(scene, run, against);
  add_series(scene, run, &against.trajectory);
  record_position_scale(run);
  keep_plotted_states(scene, run);
  run.summarised = true;
}

}  // namespace bb
