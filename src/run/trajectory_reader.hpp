// A trajectory file brought in from any program (run --trajectory NAME@DT=FILE), read and
// checked against its case before any work (docs/output-files.md#trajectories, "In"): the
// format is the one `run --trajectories` writes.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "model/state.hpp"
#include "study/scene.hpp"

namespace bb {

/// Seconds a row's `t` may differ from its step count times dt, as a fraction of dt: a
/// program that sums its time step by step stays far inside it.
inline constexpr double kStepTimeTolerance = 1e-6;

/// One trajectory file's states, one per time of its rows, on the case's step grid.
struct ImportedTrajectory {
  std::string file;
  double dt = 0.0;
  /// Steps between two rows' times: 1 (rows at every step) or the steps per sample (rows at
  /// the samples only).
  long stride = 1;
  /// The states at step 0, stride, 2 stride, ... up to where the file ends.
  std::vector<State> states;
  /// Steps of the whole run (the case's duration); the file may end before.
  long run_steps = 0;
  /// The program's own time per step (ns) at each time after the start, when the file has
  /// the optional column `cost_ns`; empty without it.
  std::vector<double> cost_ns;

  bool samples_only() const { return stride > 1; }
  /// The step of the file's last time.
  long last_step() const { return (static_cast<long>(states.size()) - 1) * stride; }
};

/// Reads `file` as a run of `scene` at step `dt` (one of the case's). Throws CaseError
/// (`file:line: problem`, exit 2) on a missing or unreadable file, a wrong header, an
/// unknown body or one missing at a time, a value that is not a number (or not finite
/// before the run's last sample), rows out of order or off the step's grid, rows past the
/// case's end. A file that ends early is read up to its end (a last line without its
/// newline is not a row; a last time without every body neither).
ImportedTrajectory read_trajectory(const Scene& scene, double dt, const std::string& file);

}  // namespace bb
