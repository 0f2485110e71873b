#include "report/work_precision.hpp"

#include "report/format.hpp"
#include "study/metric_names.hpp"

namespace bb {

std::vector<WorkSeries> work_series(const CaseResults& results, const std::string& metric) {
  std::vector<WorkSeries> out;
  for (const RunRecord& run : results.runs) {
    const auto value = metric_value(run, metric);
    if (!value || run.status != RunStatus::Ok) continue;
    if (out.empty() || out.back().backend != run.backend) out.push_back({run.backend, {}});
    const std::optional<double> cost =
        run.cost ? std::optional<double>(run.cost->seconds_per_simulated_second) : std::nullopt;
    out.back().points.push_back({*run.dt, cost, *value});
  }
  return out;
}

std::optional<double> metric_floor(const CaseResults& results, const std::string& metric) {
  for (const std::string& name : error_metric_names())
    if (name == metric) return results.reference_floor.get(metric);
  const auto found = results.observable_floor.find(metric);
  return found == results.observable_floor.end() ? std::nullopt
                                                 : std::optional<double>(found->second);
}

Table cheapest_step_table(const CaseResults& results, const std::string& metric, double target) {
  Table t;
  t.headers = {"backend", "cheapest dt s", metric, "s per sim s"};
  t.right_aligned = {false, true, true, true};
  for (const WorkSeries& s : work_series(results, metric)) {
    const WorkPoint* best = nullptr;
    // The sweep runs from the largest dt down, so the first point within target is cheapest.
    for (const WorkPoint& p : s.points)
      if (p.error <= target) {
        best = &p;
        break;
      }
    if (best == nullptr)
      t.rows.push_back({s.backend, "not reached", "-", "-"});
    else
      t.rows.push_back(
          {s.backend, format_dt(best->dt), format_value(best->error), format_value(best->cost)});
  }
  return t;
}

}  // namespace bb
