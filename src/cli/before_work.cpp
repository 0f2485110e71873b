#include <fmt/format.h>

#include <cmath>

#include "cli/commands.hpp"
#include "cli/output_folder.hpp"
#include "report/format.hpp"
#include "run/map_budget.hpp"
#include "study/case_error.hpp"

namespace bb::cli {

void check_before_work(const std::vector<Scene>& scenes, const RunOptions& options) {
  for (const Scene& scene : scenes) {
    check_run_options(scene, options);
    check_output_names(scene);
    // Leaving report_dt out is allowed (a quick look at one dt), but the tables say nothing.
    bool has_report_dt = options.dts.empty();
    for (double dt : options.dts)
      has_report_dt = has_report_dt || std::abs(dt - scene.report_dt) <= 1e-9 * dt;
    if (!has_report_dt)
      fmt::print(stderr,
                 "beachball: note: --dt leaves out {}'s report_dt ({} s): its table, plots and "
                 "gates at report_dt will be empty\n",
                 scene.name, format_dt(scene.report_dt));
  }
}

void say_map_sizes(const std::vector<Scene>& scenes, const RunOptions& options) {
  for (const Scene& scene : scenes)
    if (const std::string size = map_size_text(scene, options); !size.empty())
      fmt::print(stderr, "beachball: note: {}\n", size);
  std::fflush(stderr);
}

RunOptions with_imports(const std::vector<Scene>& scenes, const RunOptions& options) {
  if (options.import_files.empty()) return options;
  // A trajectory is a run of one case: with several, which one it is would be a guess.
  if (scenes.size() != 1)
    throw CaseError("--trajectory", 0,
                    "a trajectory is a run of one case, and the command has " +
                        std::to_string(scenes.size()) +
                        " cases: give the one case file the trajectories belong to");
  RunOptions out = options;
  out.imports = load_imports(scenes.front(), options.import_files);
  return out;
}

}  // namespace bb::cli
