#include "run/map_outcome.hpp"

namespace bb {

std::string map_outcome_name(MapOutcome outcome) {
  switch (outcome) {
    case MapOutcome::Ok:
      return "ok";
    case MapOutcome::PastOnset:
      return "past the onset";
    case MapOutcome::Diverged:
      return "diverged";
    case MapOutcome::Unsupported:
      return "unsupported";
    case MapOutcome::Failed:
      return "failed (crashed, timed out, capped or an error)";
    case MapOutcome::Absent:
      break;
  }
  return "not run";
}

MapOutcome map_outcome(const Scene& scene, const RunRecord* run) {
  if (run == nullptr) return MapOutcome::Absent;
  switch (run->status) {
    case RunStatus::Ok:
      break;
    case RunStatus::Diverged:
      return MapOutcome::Diverged;
    case RunStatus::Unsupported:
      return MapOutcome::Unsupported;
    default:
      return MapOutcome::Failed;
  }
  const Sweep& sweep = *scene.sweep;
  if (sweep.onset.empty()) return MapOutcome::Ok;
  const std::optional<double> v = run_quantity(*run, sweep.onset);
  return v && *v > sweep.onset_above ? MapOutcome::PastOnset : MapOutcome::Ok;
}

bool ran_to_an_outcome(MapOutcome outcome) {
  return outcome == MapOutcome::Ok || outcome == MapOutcome::PastOnset ||
         outcome == MapOutcome::Diverged;
}

}  // namespace bb
