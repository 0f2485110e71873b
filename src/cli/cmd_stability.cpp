#include <fmt/format.h>

#include "cli/commands.hpp"
#include "cli/output_folder.hpp"
#include "cli/progress.hpp"
#include "model/text.hpp"
#include "report/json_writer.hpp"
#include "report/markdown_text.hpp"
#include "report/summary_tables.hpp"
#include "report/table.hpp"
#include "run/engine_catalogue.hpp"
#include "run/interrupt.hpp"
#include "run/stability.hpp"
#include "study/backend_names.hpp"
#include "study/case_error.hpp"

namespace bb::cli {

namespace {

/// The stability search's own files, named apart from a `run`'s <case>.json, .csv and .md
/// so that both can share a folder.
std::vector<std::string> stability_file_names(const Scene& scene) {
  return {scene.name + "-stability.json", scene.name + "-stability.md"};
}

std::string stability_page(const CaseResults& results) {
  const Scene& scene = *results.scene;
  return fmt::format(
      "# {} - {}: largest stable step\n\nEvery backend searched from dt {:g} s to {:g} s; the "
      "results JSON beside this page has the same numbers (`stability`).\n\n{}",
      scene.name, markdown_text(scene.title), scene.stability.dt_min, scene.stability.dt_max,
      render_markdown(stability_table(results)));
}

/// The backends a stability search of `scene` runs: those that run it, but the reference.
std::vector<std::string> searched(const Scene& scene) {
  std::vector<std::string> out = runnable_backend_names(scene, engine_catalogue());
  std::erase(out, kReferenceName);
  return out;
}

}  // namespace

int stability_command(const std::vector<std::string>& paths, const std::string& out,
                      const RunOptions& options) {
  const std::vector<std::string>& backends = options.backends;
  const std::vector<Scene> scenes = load_cases(paths);
  const Registry registry = Registry::load();
  for (const Scene& scene : scenes) {
    const std::vector<std::string> known = backend_names(scene, engine_catalogue());
    for (const std::string& b : backends)
      if (b == kReferenceName || std::find(known.begin(), known.end(), b) == known.end())
        throw CaseError(scene.file, 0,
                        "--backends names '" + b + "'; the stability search runs: " +
                            joined(searched(scene)) + " (not the adaptive reference)");
  }
  check_before_work(scenes, {});
  const OutputFolder folder(out);
  for (const Scene& scene : scenes)
    check_outputs_are_ours(folder.path(), stability_file_names(scene));
  for (const Scene& scene : scenes) {
    Progress progress(static_cast<int>(backends_for(scene, registry).all.size()));
    CaseResults results;
    results.scene = &scene;
    results.stability = find_stability_all(
        scene, registry, backends, options.jobs,
        [&](const std::string& b) { progress.advance(scene.name + ": " + b); }, options.isolation,
        options.timeout, {}, options.cache);
    const std::vector<std::string> names = stability_file_names(scene);
    {
      const DeferSignals writing;
      FileBatch batch(folder.path());
      batch.write(names[0], results_json(results).dump(2) + "\n");
      batch.write(names[1], stability_page(results));
      batch.commit();
    }
    fmt::print(
        "{} - {}: largest stable step, dt from {:g} s to {:g} s\n\n{}\nwritten: {}/{} and .md\n\n",
        scene.name, scene.title, scene.stability.dt_min, scene.stability.dt_max,
        render_text(stability_table(results)), out, names[0]);
    std::fflush(stdout);
    stop_if_interrupted_after(out + "/" + names[0]);
  }
  return kExitOk;
}

}  // namespace bb::cli
