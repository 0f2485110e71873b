#include "run/run_summary.hpp"

#include <algorithm>

#include "scene/motion.hpp"

namespace bb {

void add_observables(const Scene& scene, RunRecord& run, const RunRecord& against) {
  for (const Observe& o : scene.observes) {
    ObservableResult r{o.name, {}, std::nullopt};
    if (run.status == RunStatus::Ok)
      r.measured = measure(scene, o, run.trajectory);
    else
      r.measured.note = "run " + status_name(run.status);
    // A kind with a formula (terminal_velocity) is compared with the formula's value.
    if (const auto formula = formula_value(scene, o))
      r.reference = formula;
    else if (against.status == RunStatus::Ok)
      r.reference = measure(scene, o, against.trajectory).value;
    run.observables.push_back(r);
  }
}

void add_series(const Scene& scene, RunRecord& run, const Trajectory* reference) {
  const Trajectory& t = run.trajectory;
  run.energy.clear();
  run.distance.clear();
  for (const State& s : t.states) run.energy.push_back(total_energy(scene, s));
  if (reference == nullptr || reference->states.empty()) return;
  for (std::size_t j = 0; j < t.states.size() && j < reference->states.size(); ++j) {
    double worst = 0.0;
    for (std::size_t b = 0; b < t.states[j].size(); ++b)
      worst = std::max(worst, (t.states[j][b].position - reference->states[j][b].position).norm());
    run.distance.push_back(worst);
  }
}

void keep_plotted_states(const Scene& scene, RunRecord& run) {
  std::vector<State>& states = run.trajectory.states;
  if (!run.dt || *run.dt != scene.report_dt) {
    states.clear();
    states.shrink_to_fit();
    return;
  }
  for (State& s : states)
    if (s.size() > kPlottedBodies) {
      s.resize(kPlottedBodies);
      s.shrink_to_fit();
    }
}

void summarise_in_child(const Scene& scene, RunRecord& run, const RunRecord& reference) {
  if (run.status == RunStatus::Ok)
    run.errors = compare(scene, run.trajectory, reference.trajectory);
  add_observables(scene, run, reference);
  add_series(scene, run, &reference.trajectory);
  keep_plotted_states(scene, run);
  run.summarised = true;
}

}  // namespace bb
