#include "report/cost_noise.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "report/format.hpp"
#include "run/cost.hpp"

namespace bb {

namespace {

void count(const RunRecord& run, CostNoise& noise) {
  if (!run.cost || run.cost->repeats < 3) return;
  ++noise.judged;
  if (!timed_on_a_busy_machine(*run.cost)) return;
  ++noise.busy;
  noise.worst = std::max(noise.worst, run.cost->ns_per_step / run.cost->ns_per_step_min);
}

std::string busy_mark(const std::optional<Cost>& cost) {
  return cost && timed_on_a_busy_machine(*cost) ? "~" : "";
}

}  // namespace

CostNoise cost_noise(const CaseResults& results) {
  CostNoise noise;
  count(results.reference_run, noise);
  for (const RunRecord& run : results.runs) count(run, noise);
  return noise;
}

std::string cost_noise_warning(const CaseResults& results) {
  const CostNoise noise = cost_noise(results);
  if (noise.busy == 0) return "";
  return fmt::format(
      "Cost was timed on a busy machine: in {} of the {} runs timed three times or more, the "
      "median repeat took more than {:g} times the fastest (up to {:.2g} times). Something "
      "else was using the CPU, and those medians (marked ~) are inflated by it: compare costs "
      "only between unmarked runs, or rerun on an idle machine.",
      noise.busy, noise.judged, kBusyMedianOverMin, noise.worst);
}

std::string cost_ns_cell(const std::optional<Cost>& cost) {
  return busy_mark(cost) +
         format_ns(cost ? std::optional<double>(cost->ns_per_step) : std::nullopt);
}

std::string cost_seconds_cell(const std::optional<Cost>& cost) {
  return busy_mark(cost) +
         format_value(cost ? std::optional<double>(cost->seconds_per_simulated_second)
                           : std::nullopt);
}

}  // namespace bb
