// Results crossing from a child process to its parent, as bytes. Doubles travel as their
// exact bits, so an isolated run reports exactly what an in-process run would.
#pragma once

#include <string>
#include <vector>

#include "run/cost.hpp"
#include "run/results.hpp"
#include "run/stability.hpp"

namespace bb::wire {

std::string encode(const RunRecord& run);
RunRecord decode_run(const std::string& bytes);

/// Several runs, in order (one sweep point's).
std::string encode(const std::vector<RunRecord>& runs);
std::vector<RunRecord> decode_runs(const std::string& bytes);
/// Several timings, in order (one child's cost pass over a backend's runs).
std::string encode(const std::vector<Timing>& timings);
std::vector<Timing> decode_timings(const std::string& bytes);

std::string encode(const StabilityTrial& trial);
StabilityTrial decode_trial(const std::string& bytes);

}  // namespace bb::wire
