// Everything `beachball run` does for one case: the reference, every backend at every dt,
// the metrics against the reference, the cost pass, the fitted orders and the gates.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "run/cost.hpp"
#include "run/import_backend.hpp"
#include "run/registry.hpp"
#include "run/results.hpp"
#include "run/run_cache.hpp"
#include "run/shard.hpp"

namespace bb {

struct RunOptions {
  std::vector<std::string> backends;  ///< empty: all; "reference" is always run
  std::vector<double> dts;            ///< empty: the case's sweep
  int jobs = 1;                       ///< accuracy runs in parallel
  bool cost = true;                   ///< run the cost pass
  bool sweep = true;                  ///< run the case's [[sweep]], if it has one
  /// Solve the reference a second time, tighter, for its own error (the floors of the order
  /// fits and the report's plots); a check of gates, which uses neither, does without.
  bool reference_self_check = true;
  CostOptions cost_options;
  /// Each run in its own child process with a time limit; false runs in this process.
  bool isolation = true;
  /// Seconds a run may take; 0 derives it from the case (see time_limit).
  double timeout = 0.0;
  /// Results kept between invocations: reused where the key matches, and kept when new;
  /// null keeps nothing.
  RunCache* cache = nullptr;
  /// This invocation's share of the work (shard.hpp); none: all of it.
  std::optional<Shard> shard;
  /// A folder that the reference and every accuracy run write their state at every step
  /// into, one file each (run --trajectories, trajectory_names.hpp); those runs are never
  /// taken from kept results, which hold no steps. "": none written.
  std::string trajectories;
  /// Programs' trajectories of the case (run --trajectory NAME@DT=FILE), each a backend row
  /// that runs at its files' steps only, whatever --backends and --dt select; never timed.
  std::vector<std::shared_ptr<const ImportBackend>> imports;
  /// The --trajectory options as given, read into `imports` once the case is loaded.
  std::vector<TrajectoryImport> import_files;
  /// Called after each piece of work with what was done, e.g. "bullet 1/60"; may be called
  /// from several threads at once, never concurrently.
  std::function<void(const std::string&)> on_progress;
  /// Called with a line to say to the user as the work goes (a map's estimated time, once
  /// its first point has run); from the thread that runs the case.
  std::function<void(const std::string&)> on_note;
};

/// Whether `options` select the backend called `name` (no --backends: every one).
bool backend_wanted(const RunOptions& options, const std::string& name);
/// Whether `options` run the backend called `name` on `scene`: selected, and in the shard.
bool backend_runs(const RunOptions& options, const Scene& scene, const std::string& name);

/// Seconds an accuracy run of `scene` at `dt` may take: `timeout` when given, else 10 s
/// plus 20 microseconds per step per body and spring.
double time_limit(const Scene& scene, double dt, double timeout);
/// Seconds a child may take for `steps` steps of `scene` (time_limit's rule, by steps).
double steps_time_limit(const Scene& scene, double steps);

/// How many times run_case calls on_progress for this scene and these options.
int progress_units(const Scene& scene, const Registry& registry, const RunOptions& options);

/// Throws CaseError (exit 2) when `options` name a backend or a dt that `scene` does not
/// have; commands call it for every case before they create or write anything.
void check_run_options(const Scene& scene, const RunOptions& options);

/// Throws CaseError when an option names a backend or dt the case does not have.
CaseResults run_case(const Scene& scene, const Registry& registry, const RunOptions& options);

/// Backends and steps a check runs besides its gates' (a baseline's rows).
struct RunSelection {
  std::vector<std::string> backends;
  std::vector<double> dts;
};

/// Runs only what the case's gates need (report_dt, gated backends, no cost) and what `also`
/// names (each of its backends at each of its steps), and checks the gates; `base` gives
/// jobs, isolation and timeout.
CaseResults run_gates(const Scene& scene, const Registry& registry, const RunOptions& base,
                      const RunSelection& also = {});

}  // namespace bb
