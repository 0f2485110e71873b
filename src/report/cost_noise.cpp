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

KeptCosts kept_costs(const std::vector<CaseResults>& all) {
  KeptCosts out;
  const auto look = [&](const RunRecord& run) {
    if (!run.cost) return;
    ++out.timed;
    const std::string& when = run.cost->measured_at;
    if (when.empty()) return;
    ++out.kept;
    if (out.first.empty() || when < out.first) out.first = when;
    if (out.last.empty() || when > out.last) out.last = when;
  };
  for (const CaseResults& r : all) {
    look(r.reference_run);
    for (const RunRecord& run : r.runs) look(run);
  }
  return out;
}

std::string kept_costs_note(const std::vector<CaseResults>& all) {
  const KeptCosts k = kept_costs(all);
  if (k.kept == 0) return "";
  const std::string when =
      k.first == k.last ? "at " + k.first : "from " + k.first + " to " + k.last;
  return fmt::format(
      "Kept costs: the costs of {} of the {} timed runs were kept from an earlier invocation, "
      "timed {} (UTC) on whatever the machine was doing then; their runs' results are the "
      "same bytes. `--fresh` times them anew.",
      k.kept, k.timed, when);
}

std::string cost_ns_cell(const std::optional<Cost>& cost) {
  return busy_mark(cost) +
         format_ns(cost ? std::optional<double>(cost->ns_per_step) : std::nullopt);
}

std::string cost_spread_cell(const std::optional<Cost>& cost) {
  if (!cost) return "-";
  return format_ns(cost->ns_per_step_min) + "-" + format_ns(cost->ns_per_step_max);
}

std::string cost_seconds_cell(const std::optional<Cost>& cost) {
  return busy_mark(cost) +
         format_value(cost ? std::optional<double>(cost->seconds_per_simulated_second)
                           : std::nullopt);
}

}  // namespace bb
