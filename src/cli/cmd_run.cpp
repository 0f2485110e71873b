#include <fmt/format.h>

#include "cli/commands.hpp"
#include "cli/folder_lock.hpp"
#include "cli/progress.hpp"
#include "report/format.hpp"
#include "report/summary_tables.hpp"
#include "run/interrupt.hpp"

namespace bb::cli {

int run_command(const std::vector<std::string>& paths, const std::string& out,
                const RunOptions& options) {
  // Every case is loaded and checked before anything runs or is written.
  const std::vector<Scene> scenes = load_cases(paths);
  const Registry registry = Registry::load();
  check_before_work(scenes, options, out);
  const FolderLock lock(out);
  for (const Scene& scene : scenes) {
    Progress progress(progress_units(scene, registry, options));
    RunOptions with_progress = options;
    with_progress.on_progress = [&](const std::string& what) { progress.advance(what); };
    const CaseResults results = run_case(scene, registry, with_progress);
    // A case's files are renamed into place together, once all are written; a signal
    // waits for that and then stops the program.
    {
      const DeferSignals writing;
      FileBatch batch(out);
      write_case_outputs(results, batch);
      batch.commit();
    }
    fmt::print("{} - {}  (report_dt = {} s)\n\n{}", scene.name, scene.title,
               format_dt(scene.report_dt), render_text(summary_table(results, scene.report_dt)));
    for (const std::string& note : run_notes(results, scene.report_dt)) fmt::print("  {}\n", note);
    fmt::print("\nwritten: {}/{}.json, .csv, .md\n\n", out, scene.name);
    stop_if_interrupted_after(out + "/" + scene.name + ".json, .csv, .md and plots");
  }
  return kExitOk;
}

}  // namespace bb::cli
