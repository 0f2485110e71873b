#include "run/results.hpp"

#include <algorithm>
#include <cmath>

#include "study/metric_names.hpp"

namespace bb {

std::optional<double> metric_value(const RunRecord& run, const std::string& metric) {
  const auto& names = error_metric_names();
  if (std::find(names.begin(), names.end(), metric) != names.end())
    return run.errors ? std::optional<double>(run.errors->get(metric)) : std::nullopt;
  for (const ObservableResult& o : run.observables)
    if (o.name == metric && o.measured.value && o.reference)
      return std::abs(*o.measured.value - *o.reference);
  return std::nullopt;
}

std::optional<double> run_quantity(const RunRecord& run, const std::string& metric) {
  if (run.status != RunStatus::Ok) return std::nullopt;
  const auto& names = error_metric_names();
  if (std::find(names.begin(), names.end(), metric) != names.end())
    return run.errors ? std::optional<double>(run.errors->get(metric)) : std::nullopt;
  for (const ObservableResult& o : run.observables)
    if (o.name == metric) return o.measured.value;
  return std::nullopt;
}

std::string status_name(RunStatus status) {
  switch (status) {
    case RunStatus::Ok:
      return "ok";
    case RunStatus::Diverged:
      return "diverged";
    case RunStatus::Unsupported:
      return "unsupported";
    case RunStatus::Crashed:
      return "crashed";
    case RunStatus::Timeout:
      return "timeout";
    case RunStatus::Error:
      return "error";
    case RunStatus::Capped:
      return "capped";
  }
  return "?";
}

namespace {

void drop_series(RunRecord& run) {
  run.trajectory = Trajectory{};
  std::vector<double>().swap(run.energy);
  std::vector<double>().swap(run.distance);
}

}  // namespace

void drop_page_series(CaseResults& results) {
  drop_series(results.reference_run);
  for (RunRecord& run : results.runs) drop_series(run);
  if (results.sweep)
    for (SweepPoint& point : results.sweep->points)
      for (RunRecord& run : point.runs) drop_series(run);
}

}  // namespace bb
