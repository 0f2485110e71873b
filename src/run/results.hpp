// What running a case produces: one RunRecord per (backend, dt), plus the reference.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "metrics/errors.hpp"
#include "metrics/observables.hpp"
#include "metrics/trajectory.hpp"
#include "scene/backend.hpp"

namespace bb {

/// How a run ended. Anything but Ok carries a reason.
enum class RunStatus { Ok, Diverged, Unsupported, Crashed, Timeout, Error };
std::string status_name(RunStatus status);

/// Time spent in step() only, from a separate serial pass.
struct Cost {
  double ns_per_step = 0.0;
  double seconds_per_simulated_second = 0.0;
  int repeats = 0;
};

struct ObservableResult {
  std::string name;  ///< "<kind>/<body>[/<n>]"
  ObservableValue measured;
  std::optional<double> reference;
};

struct RunRecord {
  std::string backend;
  std::optional<double> dt;  ///< nullopt for the adaptive reference
  RunStatus status = RunStatus::Ok;
  std::string reason;
  std::optional<double> diverged_at;  ///< simulated seconds
  long steps = 0;
  std::optional<Cost> cost;
  std::optional<ErrorMetrics> errors;
  std::vector<ObservableResult> observables;
  Settings engine_settings;
  Trajectory trajectory;  ///< kept in memory for metrics and plots; not written to JSON
};

struct ReferenceInfo {
  std::string method;
  double tolerance = 0.0;
  double self_check = 0.0;  ///< metres: largest position change at a 100x tighter tolerance
};

struct GateResult {
  Gate gate;
  std::optional<double> value;  ///< nullopt when the run has no such value
  bool passed = false;
  std::string note;  ///< why it failed without a value
};

struct CaseResults {
  const Scene* scene = nullptr;
  std::map<std::string, std::string> versions;
  ReferenceInfo reference;
  RunRecord reference_run;
  std::vector<RunRecord> runs;          ///< backends in registry order, dt largest first
  std::map<std::string, double> order;  ///< fitted slope of log position_max vs log dt
  std::vector<GateResult> gates;
};

}  // namespace bb
