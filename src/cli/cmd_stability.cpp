#include <fmt/format.h>

#include "cli/commands.hpp"
#include "cli/folder_lock.hpp"
#include "cli/progress.hpp"
#include "report/atomic_file.hpp"
#include "report/json_writer.hpp"
#include "report/summary_tables.hpp"
#include "run/interrupt.hpp"
#include "run/stability.hpp"
#include "scene/backend_names.hpp"
#include "scene/case_error.hpp"
#include "scene/text.hpp"

namespace bb::cli {

namespace {

/// The backends a stability search of `scene` runs: those that run it, but the reference.
std::vector<std::string> searched(const Scene& scene) {
  std::vector<std::string> out = runnable_backend_names(scene);
  std::erase(out, "reference");
  return out;
}

}  // namespace

int stability_command(const std::vector<std::string>& paths, const std::string& out,
                      const RunOptions& options) {
  const std::vector<std::string>& backends = options.backends;
  const std::vector<Scene> scenes = load_cases(paths);
  const Registry registry = Registry::load();
  for (const Scene& scene : scenes) {
    const std::vector<std::string> known = backend_names(scene);
    for (const std::string& b : backends)
      if (b == "reference" || std::find(known.begin(), known.end(), b) == known.end())
        throw CaseError(scene.file, 0,
                        "--backends names '" + b + "'; the stability search runs: " +
                            joined(searched(scene)) + " (not the adaptive reference)");
  }
  check_before_work(scenes, {}, out);
  const FolderLock lock(out);
  for (const Scene& scene : scenes) {
    Progress progress(static_cast<int>(backends_for(scene, registry).all.size()));
    CaseResults results;
    results.scene = &scene;
    results.stability = find_stability_all(
        scene, registry, backends, options.jobs,
        [&](const std::string& b) { progress.advance(scene.name + ": " + b); }, options.isolation,
        options.timeout);
    {
      const DeferSignals writing;
      write_file_atomically(out + "/" + scene.name + ".json", results_json(results).dump(2) + "\n");
    }
    stop_if_interrupted_after(out + "/" + scene.name + ".json");
    fmt::print(
        "{} - {}: largest stable step, dt from {:g} s to {:g} s\n\n{}\nwritten: {}/{}.json\n\n",
        scene.name, scene.title, scene.stability.dt_min, scene.stability.dt_max,
        render_text(stability_table(results)), out, scene.name);
  }
  return kExitOk;
}

}  // namespace bb::cli
