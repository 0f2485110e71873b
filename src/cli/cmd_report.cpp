#include <fmt/format.h>
#include <malloc.h>

#include "cli/commands.hpp"
#include "cli/output_folder.hpp"
#include "cli/progress.hpp"
#include "files/file_batch.hpp"
#include "report/claims_page.hpp"
#include "report/index_page.hpp"
#include "report/markdown_text.hpp"
#include "run/interrupt.hpp"
#include "run/stability.hpp"
#include "run/stopwatch.hpp"

namespace bb::cli {

namespace {

/// The bundled suite (no case named) regenerates with scripts/report; the user's own cases
/// with the command they ran. (Not the output folder: a report is the same bytes wherever
/// it is written, a merged one as an unsplit one.)
IndexSource index_source(const std::vector<std::string>& paths) {
  if (paths.empty()) return {"The bundled suite", "`scripts/report`"};
  std::string named;
  for (const std::string& p : paths) named += (named.empty() ? "" : ", ") + markdown_text(p);
  return {"The cases of " + named,
          "beachball report " + named + " (with this run's options and output folder)"};
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
  say_map_sizes(scenes, options);
  int units = 0;
  for (const Scene& scene : scenes)
    units += progress_units(scene, registry, options) +
             static_cast<int>(backends_for(scene, registry).all.size());
  Progress progress(units);
  RunOptions with_progress = options;
  with_progress.on_progress = [&](const std::string& what) { progress.advance(what); };
  with_progress.on_note = [&](const std::string& text) { progress.note(text); };
  // Each case's pages are written into the batch as soon as the case has run, and its series
  // dropped: the process stays near its starting size, and every child it forks (a fork copies
  // the parent's page tables) stays cheap. A signal rolls the batch back, pages and all, or
  // waits for the switch (a few renames).
  std::vector<CaseResults> all;
  std::vector<std::string> rotation_plots;
  {
    const KeptDrawings drawings = keep_drawings(options);
    FileBatch batch(report.target());
    for (const Scene& scene : scenes) {
      all.push_back(run_case(scene, registry, with_progress));
      Stopwatch stability;
      all.back().stability = find_stability_all(
          scene, registry, options.backends, options.jobs,
          [&](const std::string& b) { progress.advance(scene.name + ": stability of " + b); },
          options.isolation, options.timeout, known_trials(all.back().runs), options.cache);
      all.back().time_spent.stability = stability.lap();
      rotation_plots.push_back(write_case_outputs(all.back(), batch).rotation);
      drop_page_series(all.back());
      malloc_trim(0);
    }
    stop_if_interrupted("the report's index");
    batch.write("README.md",
                index_page(all, rotation_plots, options.cost, options.jobs, index_source(paths)));
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
