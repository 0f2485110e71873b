#include "run/baseline.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "study/metric_names.hpp"

namespace bb {

namespace {

bool same_step(const std::optional<double>& a, const std::optional<double>& b) {
  if (!a || !b) return !a && !b;
  return std::abs(*a - *b) <= 1e-9 * std::max(*a, *b);
}

const RunRecord* find_row(const std::vector<const RunRecord*>& rows, const RunRecord& like) {
  for (const RunRecord* r : rows)
    if (r->backend == like.backend && same_step(r->dt, like.dt)) return r;
  return nullptr;
}

/// The metrics either row has: the error metrics, then each observable, once.
std::vector<std::string> metric_names(const RunRecord& a, const RunRecord& b) {
  std::vector<std::string> names = error_metric_names();
  for (const RunRecord* r : {&a, &b})
    for (const ObservableResult& o : r->observables)
      if (std::find(names.begin(), names.end(), o.name) == names.end()) names.push_back(o.name);
  return names;
}

Change judge(double before, double now, const BaselineOptions& options) {
  if (now > before * (1.0 + options.tolerance) && now - before > options.floor)
    return Change::Worse;
  if (before > now * (1.0 + options.tolerance) && before - now > options.floor)
    return Change::Better;
  return Change::Unchanged;
}

/// Each metric of two rows that both ran to their end with `ok`.
void compare_metrics(const RunRecord& before, const RunRecord& now, const BaselineOptions& options,
                     std::vector<BaselineComparison>& out) {
  for (const std::string& metric : metric_names(before, now)) {
    BaselineComparison c{now.backend,
                         now.dt,
                         metric,
                         Change::Unchanged,
                         metric_value(before, metric),
                         metric_value(now, metric),
                         ""};
    if (c.before && c.now) {
      c.change = judge(*c.before, *c.now, options);
    } else if (c.before || c.now) {
      c.change = Change::NotCompared;
      c.note = c.now ? "no value in the baseline" : "no value now";
    } else {
      // An observable with no reference value (or none measured) on either side.
      c.change = Change::NothingToCompare;
      c.note = "no reference value";
    }
    out.push_back(c);
  }
}

/// Two rows of one backend and dt: their status, then, where both are ok, their metrics.
void compare_rows(const RunRecord& before, const RunRecord& now, const BaselineOptions& options,
                  std::vector<BaselineComparison>& out) {
  const bool was_ok = before.status == RunStatus::Ok, is_ok = now.status == RunStatus::Ok;
  if (was_ok && is_ok) return compare_metrics(before, now, options, out);
  BaselineComparison c{now.backend, now.dt, "status", Change::Unchanged, {}, {}, ""};
  c.note = status_name(before.status) + " -> " + status_name(now.status);
  if (!now.reason.empty() && !is_ok) c.note += ": " + now.reason;
  if (was_ok) {
    c.change = Change::Worse;
  } else if (is_ok) {
    c.change = Change::Better;
  } else if (before.status != now.status) {
    c.change = Change::NotCompared;
  } else {
    c.change = Change::NothingToCompare;
    c.note = status_name(now.status) + " in both";
  }
  out.push_back(c);
}

}  // namespace

std::vector<BaselineComparison> compare_with_baseline(const std::vector<const RunRecord*>& baseline,
                                                      const std::vector<const RunRecord*>& now,
                                                      const BaselineOptions& options) {
  std::vector<BaselineComparison> out;
  for (const RunRecord* run : now) {
    if (const RunRecord* kept = find_row(baseline, *run)) {
      compare_rows(*kept, *run, options, out);
    } else {
      out.push_back({run->backend, run->dt, "", Change::NotCompared, std::nullopt, std::nullopt,
                     "not in the baseline"});
    }
  }
  // A row of the baseline that was not run now: the case no longer runs that backend or dt.
  for (const RunRecord* kept : baseline)
    if (find_row(now, *kept) == nullptr)
      out.push_back({kept->backend, kept->dt, "", Change::NotCompared, std::nullopt, std::nullopt,
                     "in the baseline, not run now"});
  return out;
}

double change_ratio(const BaselineComparison& c) {
  if (!c.before || !c.now) return std::numeric_limits<double>::quiet_NaN();
  if (*c.before == 0.0) return *c.now == 0.0 ? 1.0 : std::numeric_limits<double>::infinity();
  return *c.now / *c.before;
}

}  // namespace bb
