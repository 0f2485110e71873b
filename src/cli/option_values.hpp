// Values given on the command line, checked against their stated ranges before any work:
// a value outside its range is bad input (exit 2) naming the option.
#pragma once

#include <string>
#include <vector>

#include "run/import_backend.hpp"
#include "run/shard.hpp"

namespace bb::cli {

/// The stated range of a numeric option, for checks and for --help.
struct OptionRange {
  double min;        ///< smallest value accepted
  double max;        ///< largest value accepted
  const char* unit;  ///< "s", "" for a count
};

/// --timeout: seconds a run may take (0.001 s to one day).
inline constexpr OptionRange kTimeoutRange{1e-3, 86400.0, "s"};
/// --cost-time: minimum timed seconds per run in the cost pass (1 ms to 10 min).
inline constexpr OptionRange kCostTimeRange{1e-3, 600.0, "s"};
/// --jobs: runs in parallel.
inline constexpr OptionRange kJobsRange{1.0, 256.0, ""};

/// Throws CaseError naming `option` unless `value` is finite and inside `range`.
void check_range(const std::string& option, double value, const OptionRange& range);

/// "a,b,c" as its parts; an empty list or an empty part ("a,,b", "a,") is an error naming
/// `option`.
std::vector<std::string> split_list(const std::string& option, const std::string& text);

/// "0.0166", "1/60" or "1e-3" as a finite, positive step in seconds; throws CaseError
/// naming --dt otherwise.
double parse_step(const std::string& text);

/// "NAME@DT=FILE" (--trajectory): NAME of letters, digits and - _ . +, DT as --dt takes it,
/// FILE a path; throws CaseError naming --trajectory otherwise.
TrajectoryImport parse_trajectory_import(const std::string& text);

/// "I/N", two whole numbers with 1 <= I <= N <= 10000, as a shard; throws CaseError naming
/// --shard otherwise.
Shard parse_shard(const std::string& text);

}  // namespace bb::cli
