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
  const FolderLock lock(out);
  for (const Scene& scene : scenes) {
    Progress progress(progress_units(scene, registry, options));
    RunOptions with_progress = options;
    with_progress.on_progress = [&](const std::string& what) { progress.advance(what); };
    const CaseResults results = run_case(scene, registry, with_progress);
    {
      const DeferSignals writing;
      write_case_outputs(results, out);
    }
    fmt::print("{} - {}  (report_dt = {} s)\n\n{}", scene.name, scene.title,
               format_dt(scene.report_dt), render_text(summary_table(results, scene.report_dt)));
    for (const std::string& note : run_notes(results, scene.report_dt)) fmt::print("  {}\n", note);
    fmt::print("\nwritten: {}/{}.json, .csv, .md\n\n", out, scene.name);
  }
  return kExitOk;
}

}  // namespace bb::cli
