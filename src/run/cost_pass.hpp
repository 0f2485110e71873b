// The cost pass: after every accuracy run so that no run disturbs its timing, --jobs
// measurements at once (one core each), each backend's runs timed in one child (run/cost.hpp times
// them); a batch kept from an earlier invocation (run_cache.hpp) is not timed again, and its costs
// say when they were.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "run/accuracy_jobs.hpp"
#include "run/case_runner.hpp"
#include "run/registry.hpp"

namespace bb {

/// Times the reference's run and every job's runs (`out.runs`, in the order of `jobs`) when
/// `options.cost`, filling each run's cost; `progress` is called once per run.
void time_costs(const Scene& scene, const ReferenceBackend& reference,
                const std::vector<AccuracyJob>& jobs, const RunOptions& options,
                const std::function<void(const std::string&)>& progress, CaseResults& out);

}  // namespace bb
