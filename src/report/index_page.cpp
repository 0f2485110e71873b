#include "report/index_page.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <limits>

#include "report/cost_noise.hpp"
#include "report/format.hpp"
#include "report/markdown_text.hpp"
#include "report/rotation_plot.hpp"
#include "report/table.hpp"
#include "report/time_spent.hpp"
#include "run/cost.hpp"

namespace bb {

namespace {

/// "0.291 m, p 1.00, 76 ns" with a gate mark: the error at report_dt, the order, the cost.
std::string index_cell(const CaseResults& r, const RunRecord& run) {
  if (run.status != RunStatus::Ok) return status_name(run.status);
  std::string cell =
      format_value(run.errors ? std::optional<double>(run.errors->position_max) : std::nullopt) +
      " m";
  if (const auto o = r.order.find(run.backend); o != r.order.end())
    cell += fmt::format(", p {:.2f}", o->second);
  if (run.cost) cell += ", " + cost_ns_cell(run.cost) + " ns";
  for (const GateResult& g : r.gates)
    if (g.gate.backend == run.backend) cell += g.passed ? " ✓" : " ✗";
  return cell;
}

/// The section number a course-text section starts with ("8. Wind effects" is 8); cases
/// of no section go last.
int section_number(const std::string& seed) {
  if (seed.empty() || !std::isdigit(static_cast<unsigned char>(seed[0])))
    return std::numeric_limits<int>::max();
  return std::atoi(seed.c_str());
}

/// "11/11 pass", "10/11 pass" or "none".
std::string gates_passed(const CaseResults& r) {
  int passed = 0;
  for (const GateResult& g : r.gates) passed += g.passed;
  return r.gates.empty() ? std::string("none") : fmt::format("{}/{} pass", passed, r.gates.size());
}

/// A case's bullet above its section's table: its page, its title, its gates.
std::string case_line(const CaseResults& r) {
  return fmt::format("- [{0}]({0}.md): {1} (gates: {2})\n", r.scene->name,
                     markdown_text(r.scene->title), gates_passed(r));
}

/// A backend per row, a case per column: each cell the backend at the case's report_dt, "-"
/// where it did not run there.
Table backends_by_cases(const std::vector<const CaseResults*>& cases) {
  std::vector<std::string> backends;
  for (const CaseResults* r : cases)
    for (const RunRecord& run : r->runs)
      if (std::find(backends.begin(), backends.end(), run.backend) == backends.end())
        backends.push_back(run.backend);
  Table t;
  t.headers = {"backend"};
  for (const CaseResults* r : cases)
    t.headers.push_back(fmt::format("[{0}]({0}.md)", r->scene->name));
  t.right_aligned.assign(t.headers.size(), false);
  for (const std::string& b : backends) {
    std::vector<std::string> row = {b};
    for (const CaseResults* r : cases) {
      std::string cell = "-";
      for (const RunRecord& run : r->runs)
        if (run.backend == b && run.dt && *run.dt == r->scene->report_dt)
          cell = index_cell(*r, run);
      row.push_back(cell);
    }
    t.rows.push_back(std::move(row));
  }
  return t;
}

}  // namespace

std::string section_tables(const std::vector<CaseResults>& all) {
  std::vector<std::string> seeds;
  for (const CaseResults& r : all)
    if (std::find(seeds.begin(), seeds.end(), r.scene->seed) == seeds.end())
      seeds.push_back(r.scene->seed);
  std::stable_sort(seeds.begin(), seeds.end(), [](const std::string& a, const std::string& b) {
    return section_number(a) < section_number(b);
  });
  const std::size_t cases_per_table = kMaxIndexColumns - 1;
  std::string out;
  for (const std::string& seed : seeds) {
    std::vector<const CaseResults*> cases;
    for (const CaseResults& r : all)
      if (r.scene->seed == seed) cases.push_back(&r);
    out += "\n### " +
           (seed.empty() ? std::string("Cases of no course section") : markdown_text(seed)) +
           "\n\n";
    for (const CaseResults* r : cases) out += case_line(*r);
    // A section of more cases than fit is split into tables of the same width.
    for (std::size_t first = 0; first < cases.size(); first += cases_per_table) {
      const std::vector<const CaseResults*> part(
          cases.begin() + static_cast<std::ptrdiff_t>(first),
          cases.begin() +
              static_cast<std::ptrdiff_t>(std::min(cases.size(), first + cases_per_table)));
      out += "\n" + render_markdown(backends_by_cases(part));
    }
  }
  return out;
}

std::string index_page(const std::vector<CaseResults>& all,
                       const std::vector<std::string>& rotation_plots, bool timed, int jobs,
                       const IndexSource& source) {
  const std::string sections = section_tables(all);
  // The cases whose bodies turn: each page's rotation plot, gathered here (where drawn).
  std::string rotation;
  for (std::size_t i = 0; i < all.size(); ++i)
    if (!turning_bodies(*all[i].scene).empty())
      rotation +=
          fmt::format("### [{0}]({0}.md)\n\n", all[i].scene->name) +
          (rotation_plots[i].empty()
               ? std::string("No rotation plot was drawn; the case's page says why.\n\n")
               : fmt::format("![{0}: rotation]({1})\n\n", all[i].scene->name, rotation_plots[i]));
  if (!rotation.empty())
    rotation =
        "\n## Rotation\n\nThe cases whose bodies turn: each turning body's angle about "
        "z and angular velocity (2D), or the tilt of its spin axis and its spin about it "
        "(3D), every backend at report_dt over the reference, as on the case's page.\n\n" +
        rotation;
  // The cases with a [[sweep]]: the published benchmarks rerun, predictability.
  std::string sweeps;
  for (const CaseResults& r : all)
    if (r.sweep && r.sweep->second_parameter.empty())
      sweeps +=
          fmt::format("- [{0}]({0}.md): `{1}` over {2} values; {3}\n", r.scene->name,
                      r.sweep->parameter, r.sweep->points.size(), markdown_text(r.scene->title));
    else if (r.sweep)
      sweeps += fmt::format("- [{0}]({0}.md): a map of `{1}` by `{2}`, {3} points; {4}\n",
                            r.scene->name, r.sweep->parameter, r.sweep->second_parameter,
                            r.sweep->points.size(), markdown_text(r.scene->title));
  if (!sweeps.empty())
    sweeps =
        "**Sweeps** (one parameter varied, or two as a map, every backend at each value; the "
        "published benchmarks rerun):\n\n" +
        sweeps + "\n";
  // The cases whose costs were timed on a busy machine.
  std::string busy;
  for (const CaseResults& r : all)
    if (cost_noise(r).busy > 0)
      busy += fmt::format("{}[{}]({}.md) ({} of {})", busy.empty() ? "" : ", ", r.scene->name,
                          r.scene->name, cost_noise(r).busy, cost_noise(r).judged);
  if (!busy.empty())
    busy = fmt::format(
        "**Cost noise**: some runs were timed on a busy machine (their median repeat took more "
        "than {:g} times the fastest; marked ~): {}.\n\n",
        kBusyMedianOverMin, busy);
  std::string kept = kept_costs_note(all);
  // The note begins "Kept costs:", set in bold here.
  if (!kept.empty()) kept = "**Kept costs**:" + kept.substr(11) + "\n\n";
  return "# beachball report\n\n" + source.what +
         ", one page per case: the scene, every backend's error against the GSL reference and "
         "its cost, the whole dt sweep with work-precision diagrams, trajectories and energy, "
         "the stability search, the gates and the engine settings used. Regenerate with " +
         source.regenerate +
         "; only cost figures and the time each part took change ([where the time "
         "went](#where-the-time-went)).\n\n"
         "**[Claims ledger](claims.md)**: the course text's sentences, each with its verdict "
         "per backend and the numbers behind it.\n\n" +
         sweeps + busy + kept +
         "\n## At report_dt, by course section\n\nOne table per section of the course text: a "
         "row per backend its cases run, a column per case (each case's title and gates are "
         "listed above its table). Each cell: position_max against the reference at the "
         "case's report_dt, the observed order of convergence p over the sweep (only where the "
         "sweep has an asymptotic range; the case page says why not), the median cost of one "
         "step, and ✓ or ✗ where a gate covers the backend; - where the backend did not run "
         "the case.\n" +
         sections + rotation + (timed ? time_spent_section(all, jobs) : "");
}

}  // namespace bb
