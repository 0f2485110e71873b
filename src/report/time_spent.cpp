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

/// Seconds of step() calls in `run`: from its cost, or where it has none (the reference, a
/// run that diverged) its own blocks of steps, timed between samples.
double step_seconds(const RunRecord& run) {
  return run.cost ? run.cost->ns_per_step * 1e-9 * static_cast<double>(run.steps)
                  : run.step_seconds;
}

/// What the accuracy runs took: `runs` that ran in `seconds` on `jobs`, and `reused` taken
/// from kept results, which took no run's time (a per-run figure counts only the runs that
/// ran: docs/scale.md's c).
std::string accuracy_runs_text(long runs, long reused, double seconds, double steps, int jobs) {
  const std::string kept = reused == 0
                               ? ""
                               : fmt::format(
                                     " {} more were taken from kept results, not run, and are not "
                                     "counted here.",
                                     reused);
  if (runs == 0)
    return fmt::format("The accuracy runs: none ran ({:.1f} s on {} {}).{}\n\n", seconds, jobs,
                       jobs == 1 ? "job" : "jobs", kept);
  return fmt::format(
      "The accuracy runs: {} ran (the references and every backend at every dt), {:.1f} s on {} "
      "{}, so {:.3f} s of a core per run on average.{} Their steps alone (from their costs; the "
      "references' solves, the self-check's too, and runs without a cost from their own timed "
      "steps) take {:.1f} s of one core: however little else the harness did, the accuracy runs "
      "would take no "
      "less than {:.1f} s with --jobs {}.\n\n",
      runs, seconds, jobs, jobs == 1 ? "job" : "jobs", seconds * jobs / static_cast<double>(runs),
      kept, steps, steps / jobs, jobs);
}

/// The accuracy runs with a cost, timed two ways: their costs times their steps, and their own
/// blocks of steps between samples (every step, with whatever observes each step).
struct TwoTimings {
  double from_costs = 0.0;
  double own_blocks = 0.0;
};

/// What the runs' own timing says beside their costs: a run's blocks of steps hold what
/// observes every step (reading the state, the observers) and run in a child process (new, or
/// shared with a few other runs), where a cost times step() alone, repeated in a loop of its own.
std::string own_timing_text(const TwoTimings& t) {
  if (t.from_costs <= 0.0 || t.own_blocks <= 0.0) return "";
  return fmt::format(
      "Timed in the runs themselves (their blocks of steps between samples, with whatever "
      "observes every step and in a child process), the runs with a cost stepped for "
      "{:.1f} s of one core, {:.2f} times the {:.1f} s their costs give (step() alone, repeated "
      "in a loop of its own).\n\n",
      t.own_blocks, t.own_blocks / t.from_costs, t.from_costs);
}

/// Seconds of a core the steps alone took in one part of the work, and the part's name.
struct StepPart {
  const char* name;
  double seconds;
};

/// Seconds of the sweep runs' blocks of steps that this invocation ran.
double sweep_step_seconds(const CaseResults& r) {
  double out = 0.0;
  if (r.sweep)
    for (const SweepPoint& point : r.sweep->points)
      for (const RunRecord& run : point.runs) out += run.step_seconds;
  return out;
}

/// The whole report against its floor: the parts' wall time (`wall`, pages aside) over the
/// seconds its steps took of a core divided by the jobs.
std::string floor_text(const std::vector<StepPart>& parts, double wall, int jobs) {
  double steps = 0.0;
  std::string each;
  for (const StepPart& p : parts) {
    steps += p.seconds;
    each += fmt::format("{}{} {:.1f} s", each.empty() ? "" : ", ", p.name, p.seconds);
  }
  if (steps <= 0.0) return "";
  const double floor = steps / jobs;
  return fmt::format(
      "The whole report's floor: its steps alone took {:.1f} s of one core ({}), so {:.1f} s on "
      "{} {}. Its runs took {:.1f} s (the table's total, pages aside): **{:.2f} times its "
      "floor**.\n\n",
      steps, each, floor, jobs, jobs == 1 ? "job" : "jobs", wall, wall / floor);
}

}  // namespace

std::string time_spent_section(const std::vector<CaseResults>& all, int jobs) {
  TimeSpent sum;
  // The accuracy runs this report ran, and what their steps alone take of one core (their
  // costs); a run taken from kept results took no run's time, and is counted apart.
  long runs = 0, reused = 0;
  double steps = 0.0;
  TwoTimings timed;
  const auto count = [&](const RunRecord& run) {
    ++(run.reused ? reused : runs);
    if (run.reused) return;
    steps += step_seconds(run);
    if (run.cost) timed.from_costs += step_seconds(run), timed.own_blocks += run.step_seconds;
  };
  for (const CaseResults& r : all) {
    count(r.reference_run);
    steps += r.time_spent.self_check_steps;
    for (const RunRecord& run : r.runs) count(run);
  }
  std::vector<const CaseResults*> cases;
  double cost_steps = 0.0, stability_steps = 0.0, sweep_steps = 0.0;
  for (const CaseResults& r : all) {
    cost_steps += r.time_spent.cost_steps;
    for (const StabilityResult& s : r.stability) stability_steps += s.step_seconds;
    sweep_steps += sweep_step_seconds(r);
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
         "parallel, measured), the cost pass, the stability search and the sweeps; "
         "writing the pages is not counted. Measured like cost, so they change from one run "
         "to the next.\n\n" +
         accuracy_runs_text(runs, reused, sum.accuracy, steps, jobs) + own_timing_text(timed) +
         floor_text({{"accuracy runs, from their costs or their timed steps", steps},
                     {"the cost pass's timed steps", cost_steps},
                     {"the stability trials' step loops", stability_steps},
                     {"the sweep runs' steps", sweep_steps}},
                    sum.total(), jobs) +
         render_markdown(t);
}

}  // namespace bb
