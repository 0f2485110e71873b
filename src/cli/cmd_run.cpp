#include <fmt/format.h>

#include <filesystem>
#include <optional>

#include "cli/commands.hpp"
#include "cli/output_folder.hpp"
#include "cli/progress.hpp"
#include "report/format.hpp"
#include "report/summary_tables.hpp"
#include "run/interrupt.hpp"
#include "run/trajectory_names.hpp"

namespace bb::cli {

namespace {

/// The files in `folder` (a batch's trajectories folder, not yet switched in).
int files_in(const std::string& folder) {
  std::error_code ec;
  int n = 0;
  for (auto it = std::filesystem::directory_iterator(folder, ec);
       !ec && it != std::filesystem::directory_iterator(); it.increment(ec))
    ++n;
  return n;
}

}  // namespace

int run_command(const std::vector<std::string>& paths, const std::string& out,
                const RunOptions& given, bool all_runs_first, bool trajectories) {
  // Every case is loaded and checked before anything runs or is written.
  const std::vector<Scene> scenes = load_cases(paths);
  const RunOptions options = with_imports(scenes, given);
  const Registry registry = Registry::load();
  check_before_work(scenes, options);
  if (trajectories)
    for (const Scene& scene : scenes) check_trajectory_names(scene);
  const OutputFolder folder(out);
  // A file in the way that beachball did not write stops the command now, not after the runs.
  for (const Scene& scene : scenes) {
    check_outputs_are_ours(folder.path(), case_output_names(scene));
    check_trajectories_are_ours(folder.path(), scene.name, trajectories);
  }
  say_map_sizes(scenes, options);
  const auto run_one = [&](const Scene& scene, const std::string& steps_folder) {
    Progress progress(progress_units(scene, registry, options));
    RunOptions with_progress = options;
    with_progress.trajectories = steps_folder;
    with_progress.on_progress = [&](const std::string& what) { progress.advance(what); };
    with_progress.on_note = [&](const std::string& text) { progress.note(text); };
    return run_case(scene, registry, with_progress);
  };
  std::vector<CaseResults> ready;
  if (all_runs_first)
    for (const Scene& scene : scenes) ready.push_back(run_one(scene, ""));
  for (std::size_t i = 0; i < scenes.size(); ++i) {
    const Scene& scene = scenes[i];
    // With --trajectories the case's batch comes first: its runs write their steps into it
    // from their child processes, and a stop before the switch takes them away with it.
    std::optional<FileBatch> batch;
    std::string steps_folder;
    if (trajectories) {
      batch.emplace(folder.path());
      steps_folder = batch->folder_for(trajectory_folder_name(scene.name));
    }
    const CaseResults results = all_runs_first ? std::move(ready[i]) : run_one(scene, steps_folder);
    const int steps_files = trajectories ? files_in(steps_folder) : 0;
    // A case's files replace its earlier set as one unit, once all are written; a signal
    // stops the writing and rolls it back, or waits for the switch (a few renames).
    {
      const KeptDrawings drawings = keep_drawings(options);
      if (!batch) batch.emplace(folder.path());
      write_case_outputs(results, *batch);
      for (const std::string& old : recorded_case_files(folder.path(), scene.name))
        batch->drop(old);
      const DeferSignals switching;
      batch->commit();
    }
    fmt::print("{} - {}  (report_dt = {} s)\n\n{}", scene.name, scene.title,
               format_dt(scene.report_dt), render_text(summary_table(results, scene.report_dt)));
    for (const std::string& note : run_notes(results, scene.report_dt)) fmt::print("  {}\n", note);
    fmt::print("\nwritten: {}/{}.json, .csv, .md\n", out, scene.name);
    if (trajectories)
      fmt::print("         {}/{}/: {} files, a run's state at every step{}\n", out,
                 trajectory_folder_name(scene.name), steps_files,
                 options.cache ? " (every run ran: kept results hold no steps)" : "");
    fmt::print("\n");
    std::fflush(stdout);
    stop_if_interrupted_after(out + "/" + scene.name + ".json, .csv, .md and plots");
  }
  return kExitOk;
}

}  // namespace bb::cli
