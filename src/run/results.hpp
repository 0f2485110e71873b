// What running a case produces: one RunRecord per (backend, dt), plus the reference.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "metrics/errors.hpp"
#include "metrics/order.hpp"
#include "metrics/trajectory.hpp"
#include "observe/observables.hpp"
#include "run/claim_result.hpp"
#include "seam/backend.hpp"

namespace bb {

/// How a run ended. Anything but Ok carries a reason. Capped: it ran to the end, but its
/// engine held a body at a limit of its own (Box2D's 2 m per step; the reason names the
/// cap, the body and when): its numbers are measured and shown, and nothing trusts them.
enum class RunStatus { Ok, Diverged, Unsupported, Crashed, Timeout, Error, Capped };
std::string status_name(RunStatus status);
/// Whether a run went to its end with a trajectory to measure: ok, or capped.
inline bool ran_to_end(RunStatus status) {
  return status == RunStatus::Ok || status == RunStatus::Capped;
}

/// Time spent in step() only, from a separate pass (one timing per core): the median over repeats,
/// with the fastest and slowest repeat beside it.
struct Cost {
  double ns_per_step = 0.0;
  double seconds_per_simulated_second = 0.0;
  int repeats = 0;
  double ns_per_step_min = 0.0;
  double ns_per_step_max = 0.0;
  /// "" when timed by this invocation; else when (UTC, ISO 8601) a kept cost was timed.
  std::string measured_at;
};

struct ObservableResult {
  std::string name;  ///< "<kind>/<body>[/<n>]"
  ObservableValue measured;
  std::optional<double> reference;
};

/// One run at one step. Stable means bounded (energy_growth.hpp): no divergence, and an
/// energy that neither compounds nor runs away; drift that adds is stable. A run its engine
/// reset, or held at a cap of its own, is not stable (engine_interventions.hpp).
struct StabilityTrial {
  bool stable = false;
  std::string reason;  ///< what the energy did (a stable drift says so too), or why it failed
  /// "bounded", "drift", "compounds", "runaway", "diverged" (a reset by the engine too),
  /// "capped" (held at the engine's cap), or "failed" (the run did not finish: an
  /// exception, a crash, a timeout)
  std::string growth;
  /// Seconds of the trial's step loop (its steps and the watch on each), measured like cost:
  /// the stability search's share of a report's floor; never written to the results.
  double step_seconds = 0.0;
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
  std::string messages;  ///< what the engine printed during an ok run, if anything
  /// The stability search's trial at this dt, judged on this run's own steps: set when the
  /// dt is one the search begins with (its dt_min or dt_max), so it is not run twice.
  std::optional<StabilityTrial> stability_trial;
  /// What the page plots, not written to JSON: at report_dt the first few bodies' states
  /// (run_summary.hpp), elsewhere times and events only, unless the errors are measured in
  /// the parent (the reference's own run, and the fallback of docs/design.md).
  Trajectory trajectory;
  std::vector<double> energy;  ///< total energy at each sample time (J)
  /// Largest position distance from the reference (m; in the fallback of docs/design.md, from the
  /// backend's finest run)
  std::vector<double> distance;
  double position_scale = 0.0;  ///< largest |position| over the samples (m)
  double travel = 0.0;          ///< largest distance a body moves from its start (m)
  bool summarised = false;      ///< errors, observables and series measured in the child
  /// Taken from kept results, not run by this invocation (where the time went counts only
  /// runs that ran); never written to the results or the wire.
  bool reused = false;
  /// Seconds of the run's blocks of steps between samples (with the observation of each
  /// step where an observable needs it), measured like cost: a sweep run's share of a
  /// report's floor; never written to the results.
  double step_seconds = 0.0;
  /// Why its trajectory file (run --trajectories) could not be written, from its child;
  /// "" when it was, or none was asked. Never written to the results.
  std::string trajectory_problem;
};

struct ReferenceInfo {
  std::string method;
  double tolerance = 0.0;
  /// The self-check: the largest difference of each state component from a second solve
  /// by another method (self_check_method), 100 times tighter; nullopt when there was
  /// none to compare (self_check_note says why).
  std::optional<StateDifference> self_check;
  std::string self_check_method;
  std::string self_check_note;
  /// Metres: the self-check's position difference, 0 without one.
  double self_check_position() const { return self_check ? self_check->position : 0.0; }
};

struct GateResult {
  Gate gate;
  std::optional<double> value;  ///< nullopt when the run has no such value
  bool passed = false;
  std::string note;  ///< why it failed without a value
  /// What the value is measured against when it is not the reference: "" for the reference,
  /// else the self-consistency fallback's words (the backend's own run at its finest dt).
  std::string against;
};

/// How a value of `check --baseline` compares with the baseline's (run/baseline.hpp).
enum class Change {
  Worse,             ///< grew past the tolerance, or a status that left ok: fails
  Better,            ///< shrank past the tolerance, or a status that became ok
  Unchanged,         ///< within the tolerance
  NotCompared,       ///< present on one side only (a row, a value, a status change): named
  NothingToCompare,  ///< neither side has a value (no reference value, diverged in both)
};

struct BaselineComparison {
  std::string backend;
  std::optional<double> dt;  ///< nullopt for the reference's row
  std::string metric;        ///< an error metric, an observable, or "status"
  Change change = Change::Unchanged;
  std::optional<double> before, now;  ///< a metric's values in the baseline and now
  std::string note;  ///< a status change ("ok -> diverged: why"), or why not compared
};

/// A stretch of steps with one verdict, between the smallest and largest step tried in it.
struct StabilityBand {
  double from = 0.0, to = 0.0;  ///< seconds
  bool stable = false;
  std::string reason;  ///< unstable: why its smallest step failed; stable: what its largest did
};

struct StabilityResult {
  std::string backend;
  /// "bracketed", "not monotone" (stable again above an unstable band), "stable at every
  /// dt tried", "unstable at every dt tried", "unsupported"
  std::string status;
  /// Largest step found stable with every step tried below it stable too
  std::optional<double> critical_dt;
  std::optional<double> unstable_dt;  ///< smallest step found unstable
  std::string reason;                 ///< why unstable_dt failed, or why unsupported
  std::string stable_note;            ///< what critical_dt's energy did (a drift, say), if anything
  std::vector<StabilityBand> bands;   ///< from the smallest step tried to the largest
  std::optional<double> theory;       ///< seconds, where theory covers the scene
  std::string theory_formula;
  std::string theory_note;  ///< how to read the measured limit beside the theory
  int trials = 0;
  /// Seconds of the step loops of the trials this invocation ran (not those taken from kept
  /// results or from the accuracy runs); never written to the results.
  double step_seconds = 0.0;
};

/// A run's value for an error metric, or the size of an observable's difference from the
/// reference; nullopt when the run has none.
std::optional<double> metric_value(const RunRecord& run, const std::string& metric);
/// An ok run's value for an error metric, or an observable's measured value; nullopt when
/// the run has none.
std::optional<double> run_quantity(const RunRecord& run, const std::string& metric);

/// One value of a [[sweep]]: the whole case run at it, reference first, then every backend
/// at report_dt (rows as in CaseResults::runs, without what the page plots over time).
struct SweepPoint {
  double value = 0.0;
  double second_value = 0.0;  ///< a map's point: the second [[sweep]]'s value there
  std::vector<RunRecord> runs;
};

/// A [[sweep]]'s points, or a map's (two [[sweep]]s): then every value of the first with
/// every value of the second, row by row (point i * Q + j is the first's value i and the
/// second's value j).
struct SweepResults {
  std::string parameter;
  std::vector<SweepPoint> points;  ///< in the order of the case's values
  std::string second_parameter;    ///< a map's second [[sweep]]; "" for one [[sweep]]
};

/// Wall-clock seconds one case took, by the part of the work: like cost, measured, never
/// written to the results (the report's index page shows where a report's time went).
struct TimeSpent {
  double accuracy = 0.0;   ///< the reference and every backend at every dt, measured
  double cost = 0.0;       ///< the cost pass
  double stability = 0.0;  ///< the stability search
  double sweep = 0.0;      ///< the case's [[sweep]]
  /// Seconds of the cost pass's timed steps, every repeat of every run it timed: its share
  /// of the report's floor (time_spent.hpp).
  double cost_steps = 0.0;
  /// Seconds of the reference's second solve (its self-check), timed by sample blocks like
  /// every accuracy run; 0 when it was taken from kept results.
  double self_check_steps = 0.0;
  double total() const { return accuracy + cost + stability + sweep; }
};

struct CaseResults {
  const Scene* scene = nullptr;
  std::map<std::string, std::string> versions;
  ReferenceInfo reference;
  /// The reference against itself solved 100 times tighter: the floor of every error metric.
  ErrorMetrics reference_floor;
  /// The same for each observable: |value - value at the tighter tolerance|.
  std::map<std::string, double> observable_floor;
  RunRecord reference_run;
  std::vector<RunRecord> runs;  ///< backends in registry order, dt largest first
  /// Fitted slope of log position_max vs log dt, for the backends that have one.
  std::map<std::string, double> order;
  /// Per backend: the fit, with its local slopes, or why there is no order.
  std::map<std::string, OrderFit> order_fits;
  /// Per backend: the error at or above which its position_max has saturated (m).
  std::map<std::string, double> order_saturation;
  std::vector<GateResult> gates;
  /// Against the baseline's kept results, when `check --baseline` ran: empty otherwise.
  std::vector<BaselineComparison> baseline;
  /// Each [[claim]] of the case with every backend's verdict, judged once after the runs.
  std::vector<ClaimResult> claims;
  std::vector<StabilityResult> stability;  ///< empty unless a stability search ran
  std::optional<SweepResults> sweep;       ///< when the case has a [[sweep]] and it ran
  TimeSpent time_spent;
};

/// Empties what only the case's own pages read (every run's trajectory, energy and distance
/// series), once those pages are written: the index and the claims page read the rest.
void drop_page_series(CaseResults& results);

}  // namespace bb
