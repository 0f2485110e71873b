#include "report/baseline_text.hpp"

#include <fmt/format.h>

#include <cmath>
#include <map>

#include "model/text.hpp"
#include "run/baseline.hpp"

namespace bb {

std::string change_word(Change change) {
  switch (change) {
    case Change::Worse:
      return "worse";
    case Change::Better:
      return "better";
    case Change::Unchanged:
      return "unchanged";
    default:
      return "not compared";
  }
}

bool said_alone(const BaselineComparison& c) {
  return c.change == Change::Worse || c.change == Change::Better || c.change == Change::NotCompared;
}

std::string baseline_change_text(const BaselineComparison& c) {
  std::string where = c.backend + (c.dt ? " dt " + format_dt(*c.dt) : "");
  if (!c.metric.empty()) where += " " + c.metric;
  if (!c.before || !c.now) return where + ": " + c.note;
  const double ratio = change_ratio(c);
  return fmt::format("{}: {} -> {} (x{})", where, significant_digits(*c.before, 6),
                     significant_digits(*c.now, 6),
                     std::isinf(ratio) ? "inf" : significant_digits(ratio, 4));
}

std::string baseline_summary(const std::string& folder, const std::vector<CaseResults>& all,
                             int cases_without_baseline) {
  std::map<Change, int> counts;
  // Why values were not compared, and how many each.
  std::map<std::string, int> why;
  for (const CaseResults& r : all)
    for (const BaselineComparison& c : r.baseline) {
      ++counts[c.change];
      if (c.change == Change::NotCompared || c.change == Change::NothingToCompare)
        ++why[c.metric == "status" && c.change == Change::NotCompared ? "status changed" : c.note];
    }
  const int compared = counts[Change::Worse] + counts[Change::Better] + counts[Change::Unchanged];
  std::string text =
      fmt::format("baseline {}: {} compared: {} worse, {} better, {} unchanged", folder, compared,
                  counts[Change::Worse], counts[Change::Better], counts[Change::Unchanged]);
  int not_compared = 0;
  std::vector<std::string> reasons;
  for (const auto& [reason, n] : why) {
    not_compared += n;
    reasons.push_back(fmt::format("{} {}", reason, n));
  }
  if (not_compared > 0)
    text += fmt::format("; not compared: {} ({})", not_compared, joined(reasons));
  if (cases_without_baseline > 0)
    text += fmt::format("; {} case{} without a baseline", cases_without_baseline,
                        cases_without_baseline == 1 ? "" : "s");
  return text;
}

}  // namespace bb
