#include <fmt/format.h>

#include <cctype>
#include <cstdlib>
#include <limits>
#include <map>

#include "cli/commands.hpp"
#include "cli/output_folder.hpp"
#include "cli/progress.hpp"
#include "files/file_batch.hpp"
#include "report/claims_page.hpp"
#include "report/cost_noise.hpp"
#include "report/format.hpp"
#include "report/markdown_text.hpp"
#include "report/rotation_plot.hpp"
#include "report/table.hpp"
#include "report/time_spent.hpp"
#include "run/cost.hpp"
#include "run/interrupt.hpp"
#include "run/stability.hpp"
#include "run/stopwatch.hpp"

namespace bb::cli {

namespace {

/// "0.291 m, 1.00, 76 ns" with a gate mark: the error at report_dt, the order, the cost.
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

/// One table per course section, in the text's order: each case with its title and gates,
/// and a column for each backend its section's cases run (not the 35 of the whole suite).
std::string section_tables(const std::vector<CaseResults>& all) {
  std::vector<std::string> seeds;
  for (const CaseResults& r : all)
    if (std::find(seeds.begin(), seeds.end(), r.scene->seed) == seeds.end())
      seeds.push_back(r.scene->seed);
  std::stable_sort(seeds.begin(), seeds.end(), [](const std::string& a, const std::string& b) {
    return section_number(a) < section_number(b);
  });
  std::string out;
  for (const std::string& seed : seeds) {
    std::vector<std::string> backends;
    for (const CaseResults& r : all)
      if (r.scene->seed == seed)
        for (const RunRecord& run : r.runs)
          if (std::find(backends.begin(), backends.end(), run.backend) == backends.end())
            backends.push_back(run.backend);
    Table t;
    t.headers = {"case", "title", "gates"};
    t.headers.insert(t.headers.end(), backends.begin(), backends.end());
    t.right_aligned.assign(t.headers.size(), false);
    for (const CaseResults& r : all) {
      if (r.scene->seed != seed) continue;
      int passed = 0;
      for (const GateResult& g : r.gates) passed += g.passed;
      std::vector<std::string> row = {
          fmt::format("[{0}]({0}.md)", r.scene->name), markdown_text(r.scene->title),
          r.gates.empty() ? "none" : fmt::format("{}/{} pass", passed, r.gates.size())};
      for (const std::string& b : backends) {
        std::string cell = "-";
        for (const RunRecord& run : r.runs)
          if (run.backend == b && run.dt && *run.dt == r.scene->report_dt)
            cell = index_cell(r, run);
        row.push_back(cell);
      }
      t.rows.push_back(row);
    }
    out += "\n### " + (seed.empty() ? std::string("Cases of no course section") : seed) + "\n\n" +
           render_markdown(t);
  }
  return out;
}

/// The index page; with `timed` (the cost pass ran), where the time went: like the costs, a
/// report without them is the same bytes from one run to the next.
std::string index_page(const std::vector<CaseResults>& all,
                       const std::vector<std::string>& rotation_plots, bool timed, int jobs) {
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
    if (r.sweep)
      sweeps +=
          fmt::format("- [{0}]({0}.md): `{1}` over {2} values; {3}\n", r.scene->name,
                      r.sweep->parameter, r.sweep->points.size(), markdown_text(r.scene->title));
  if (!sweeps.empty())
    sweeps =
        "**Sweeps** (one parameter varied, every backend at each value; the published "
        "benchmarks rerun):\n\n" +
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
  return "# beachball report\n\nThe bundled suite, one page per case: the scene, every backend's "
         "error against the GSL reference and its cost, the whole dt sweep with work-precision "
         "diagrams, trajectories and energy, the stability search, the gates and the engine "
         "settings used. Regenerate with `scripts/report`; only cost figures and the time "
         "each part took change ([where the time went](#where-the-time-went)).\n\n"
         "**[Claims ledger](claims.md)**: the course text's sentences, each with its verdict "
         "per backend and the numbers behind it.\n\n" +
         sweeps + busy + kept +
         "\n## At report_dt, by course section\n\nOne table per section of the course text, "
         "with the backends its cases run. Each cell: position_max against the reference at the "
         "case's "
         "report_dt, the observed order of convergence p over the sweep (only where the sweep "
         "has an asymptotic range; the case page says why not), the median cost of one "
         "step, and ✓ or ✗ where a gate covers the backend.\n" +
         sections + rotation + (timed ? time_spent_section(all, jobs) : "");
}

}  // namespace

int report_command(const std::vector<std::string>& paths, const std::string& out,
                   const RunOptions& given) {
  const std::vector<Scene> scenes = load_cases(paths);
  const RunOptions options = with_imports(scenes, given);
  const Registry registry = Registry::load();
  check_before_work(scenes, options);
  const OutputFolder folder(out);
  // The new report is built beside the old one (or inside it) and switched in whole; a
  // folder that holds anything beachball did not write is refused here, before any run.
  ReportFolder report(folder);
  int units = 0;
  for (const Scene& scene : scenes)
    units += progress_units(scene, registry, options) +
             static_cast<int>(backends_for(scene, registry).all.size());
  Progress progress(units);
  RunOptions with_progress = options;
  with_progress.on_progress = [&](const std::string& what) { progress.advance(what); };
  std::vector<CaseResults> all;
  for (const Scene& scene : scenes) {
    all.push_back(run_case(scene, registry, with_progress));
    Stopwatch stability;
    all.back().stability = find_stability_all(
        scene, registry, options.backends, options.jobs,
        [&](const std::string& b) { progress.advance(scene.name + ": stability of " + b); },
        options.isolation, options.timeout, known_trials(all.back().runs), options.cache);
    all.back().time_spent.stability = stability.lap();
  }
  // Pages are written only when every case has run. A signal stops the writing and rolls it
  // back (the batch and the folder beside go), or waits for the switch (a few renames).
  {
    const KeptDrawings drawings = keep_drawings(options);
    FileBatch batch(report.target());
    std::vector<std::string> rotation_plots;
    for (const CaseResults& r : all)
      rotation_plots.push_back(write_case_outputs(r, batch).rotation);
    stop_if_interrupted("the report's index");
    batch.write("README.md", index_page(all, rotation_plots, options.cost, options.jobs));
    batch.write("claims.md", claims_page(all));
    report.drop_old_report(batch);
    const DeferSignals switching;
    batch.commit();
    report.commit();
  }
  if (!report.by_files_because().empty())
    fmt::print("note: the report was switched in file by file, not as one folder, because {}\n",
               report.by_files_because());
  fmt::print("written: {}/README.md and one page per case\n", out);
  std::fflush(stdout);
  stop_if_interrupted_after("the report in " + out);
  return kExitOk;
}

}  // namespace bb::cli
