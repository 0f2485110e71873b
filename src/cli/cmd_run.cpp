#include <fmt/format.h>

#include "cli/commands.hpp"
#include "cli/output_folder.hpp"
#include "cli/progress.hpp"
#include "report/format.hpp"
#include "report/summary_tables.hpp"
#include "run/interrupt.hpp"

namespace bb::cli {

int run_command(const std::vector<std::string>& paths, const std::string& out,
                const RunOptions& options, bool all_runs_first) {
  // Every case is loaded and checked before anything runs or is written.
  const std::vector<Scene> scenes = load_cases(paths);
  const Registry registry = Registry::load();
  check_before_work(scenes, options);
  const OutputFolder folder(out);
  // A file in the way that beachball did not write stops the command now, not after the runs.
  for (const Scene& scene : scenes) check_outputs_are_ours(folder.path(), case_output_names(scene));
  const auto run_one = [&](const Scene& scene) {
    Progress progress(progress_units(scene, registry, options));
    RunOptions with_progress = options;
    with_progress.on_progress = [&](const std::string& what) { progress.advance(what); };
    return run_case(scene, registry, with_progress);
  };
  std::vector<CaseResults> ready;
  if (all_runs_first)
    for (const Scene& scene : scenes) ready.push_back(run_one(scene));
  for (std::size_t i = 0; i < scenes.size(); ++i) {
    const Scene& scene = scenes[i];
    const CaseResults results = all_runs_first ? std::move(ready[i]) : run_one(scene);
    // A case's files replace its earlier set as one unit, once all are written; a signal
    // stops the writing and rolls it back, or waits for the switch (a few renames).
    {
      const KeptDrawings drawings = keep_drawings(options);
      FileBatch batch(folder.path());
      write_case_outputs(results, batch);
      for (const std::string& old : recorded_case_files(folder.path(), scene.name)) batch.drop(old);
      const DeferSignals switching;
      batch.commit();
    }
    fmt::print("{} - {}  (report_dt = {} s)\n\n{}", scene.name, scene.title,
               format_dt(scene.report_dt), render_text(summary_table(results, scene.report_dt)));
    for (const std::string& note : run_notes(results, scene.report_dt)) fmt::print("  {}\n", note);
    fmt::print("\nwritten: {}/{}.json, .csv, .md\n\n", out, scene.name);
    std::fflush(stdout);
    stop_if_interrupted_after(out + "/" + scene.name + ".json, .csv, .md and plots");
  }
  return kExitOk;
}

}  // namespace bb::cli
