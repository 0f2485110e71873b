// The schedule of a case's accuracy runs, each in its own child process: the reference and
// its self-check first, then every (backend, dt). A run measures itself in its child and
// brings back only its summaries and what the page plots (run_summary.hpp).
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "reference/gsl_reference.hpp"
#include "run/case_runner.hpp"

namespace bb {

struct AccuracyJob {
  const Backend* backend;
  double dt;
};

struct AccuracyRuns {
  RunRecord reference;
  RunRecord tight;              ///< the reference solved 100 times tighter
  std::vector<RunRecord> runs;  ///< one per job, in the jobs' order
};

/// Jobs are grouped by backend, largest dt first; the runs come back in that order. They
/// start once the reference is back, the smallest dt first (the longest runs: a case's last
/// runs are short ones); each child inherits the reference at fork and measures its run
/// against it. Without an ok reference (the fallback of docs/design.md) each backend's finest run
/// goes first and writes its whole trajectory once, to a temporary file that the backend's other
/// runs read in their children; where the finest run fails, the others come back whole for
/// the caller.
AccuracyRuns run_accuracy_jobs(const Scene& scene, const ReferenceBackend& reference,
                               const std::vector<AccuracyJob>& jobs, const RunOptions& options,
                               const std::function<void(const std::string&)>& progress);

}  // namespace bb
