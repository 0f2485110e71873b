// Cost figures that show their noise: which runs were timed on a busy machine, the warning
// a page gives, and cost cells that mark them.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "run/results.hpp"

namespace bb {

struct CostNoise {
  int judged = 0;      ///< timed runs with three repeats or more (the reference included)
  int busy = 0;        ///< of those, timed on a busy machine (run/cost.hpp)
  double worst = 0.0;  ///< the largest median over fastest repeat among them
};
CostNoise cost_noise(const CaseResults& results);

/// The page's warning when some run was timed on a busy machine, else "".
std::string cost_noise_warning(const CaseResults& results);

/// Costs kept from an earlier invocation (Cost::measured_at) among `all`: how many of the
/// timed runs, and the first and last time they were timed.
struct KeptCosts {
  int kept = 0;
  int timed = 0;
  std::string first, last;
};
KeptCosts kept_costs(const std::vector<CaseResults>& all);
/// The note a page (one case) or the index (every case) gives when some costs were kept,
/// else "".
std::string kept_costs_note(const std::vector<CaseResults>& all);

/// The fastest and the slowest repeat of a run's cost, ns per step ("252894-261257").
std::string cost_spread_cell(const std::optional<Cost>& cost);

/// A cost cell in ns per step: the median, "~" in front when timed on a busy machine.
std::string cost_ns_cell(const std::optional<Cost>& cost);
/// The same in seconds of computing per simulated second.
std::string cost_seconds_cell(const std::optional<Cost>& cost);

}  // namespace bb
