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

namespace {

/// Seconds of step() calls in `run`, from its cost (0 without one).
double step_seconds(const RunRecord& run) {
  return run.cost ? run.cost->ns_per_step * 1e-9 * static_cast<double>(run.steps) : 0.0;
}

}  // namespace

std::string time_spent_section(const std::vector<CaseResults>& all, int jobs) {
  TimeSpent sum;
  // The accuracy runs, and what their steps alone take of one core (their costs).
  long runs = 0;
  double steps = 0.0;
  for (const CaseResults& r : all) {
    runs += 1 + static_cast<long>(r.runs.size());
    steps += step_seconds(r.reference_run);
    for (const RunRecord& run : r.runs) steps += step_seconds(run);
  }
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
         fmt::format(
             "The accuracy runs: {} (the references and every backend at every dt), {:.1f} s "
             "on {} {}, so {:.3f} s of a core per run on average. Their steps alone, from their "
             "costs, take {:.1f} s of one core: however little else the harness did, the "
             "accuracy runs would take no less than {:.1f} s with --jobs {}.\n\n",
             runs, sum.accuracy, jobs, jobs == 1 ? "job" : "jobs",
             runs > 0 ? sum.accuracy * jobs / static_cast<double>(runs) : 0.0, steps, steps / jobs,
             jobs) +
         render_markdown(t);
}

}  // namespace bb
