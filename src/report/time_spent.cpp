#include "report/time_spent.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "report/table.hpp"

namespace bb {

namespace {

std::vector<std::string> row(const std::string& name, const TimeSpent& t) {
  const auto seconds = [](double s) { return fmt::format("{:.1f}", s); };
  return {name,
          seconds(t.accuracy),
          seconds(t.cost),
          seconds(t.stability),
          seconds(t.sweep),
          seconds(t.total())};
}

}  // namespace

std::string time_spent_section(const std::vector<CaseResults>& all) {
  TimeSpent sum;
  std::vector<const CaseResults*> cases;
  for (const CaseResults& r : all) {
    sum.accuracy += r.time_spent.accuracy;
    sum.cost += r.time_spent.cost;
    sum.stability += r.time_spent.stability;
    sum.sweep += r.time_spent.sweep;
    cases.push_back(&r);
  }
  if (sum.total() <= 0.0) return "";
  std::stable_sort(cases.begin(), cases.end(), [](const CaseResults* a, const CaseResults* b) {
    return a->time_spent.total() > b->time_spent.total();
  });
  Table t;
  t.headers = {"case", "accuracy s", "cost pass s", "stability s", "sweep s", "total s"};
  t.right_aligned = {false, true, true, true, true, true};
  t.rows.push_back(row("all cases", sum));
  for (const CaseResults* r : cases) t.rows.push_back(row(r->scene->name, r->time_spent));
  return "\n## Where the time went\n\nWall-clock seconds of this report's runs, by the part of "
         "the work: the accuracy runs (the reference and every backend at every dt, in "
         "parallel, measured), the serial cost pass, the stability search and the sweeps; "
         "writing the pages is not counted. Measured like cost, so they change from one run "
         "to the next.\n\n" +
         render_markdown(t);
}

}  // namespace bb
