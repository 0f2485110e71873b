#include "cli/baseline_check.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "run/baseline.hpp"
#include "run/engine_catalogue.hpp"
#include "study/backend_names.hpp"
#include "study/case_error.hpp"

namespace bb::cli {

namespace fs = std::filesystem;

std::map<std::string, KeptResults> read_baselines(const std::string& folder,
                                                  const std::vector<Scene>& scenes) {
  std::error_code ec;
  const fs::file_status status = fs::status(folder, ec);
  if (!fs::exists(status)) throw CaseError(folder, 0, "no such folder (--baseline)");
  if (!fs::is_directory(status))
    throw CaseError(folder, 0, "is not a folder (--baseline takes the folder of <case>.json)");
  std::map<std::string, KeptResults> out;
  for (const Scene& scene : scenes) {
    const std::string file = (fs::path(folder) / (scene.name + ".json")).string();
    if (!fs::exists(fs::status(file, ec))) continue;
    KeptResults kept = read_results_file(file);
    if (kept.case_name != scene.name)
      throw CaseError(
          file, 0, "holds the results of case '" + kept.case_name + "', not '" + scene.name + "'");
    out.emplace(scene.name, std::move(kept));
  }
  return out;
}

RunSelection baseline_selection(const Scene& scene, const KeptResults& kept,
                                const std::optional<Shard>& shard) {
  const std::vector<std::string> names = backend_names(scene, engine_catalogue());
  RunSelection also;
  for (const RunRecord& run : kept.runs) {
    const bool known = std::find(names.begin(), names.end(), run.backend) != names.end() ||
                       run.backend == kReferenceName;
    if (known && in_shard(shard, scene, run.backend) &&
        std::find(also.backends.begin(), also.backends.end(), run.backend) == also.backends.end())
      also.backends.push_back(run.backend);
    if (!run.dt) continue;
    // The case's own step, which the kept one was written from.
    const auto step = std::find_if(scene.dt.begin(), scene.dt.end(),
                                   [&](double d) { return std::abs(d - *run.dt) <= 1e-9 * d; });
    if (step != scene.dt.end() &&
        std::find(also.dts.begin(), also.dts.end(), *step) == also.dts.end())
      also.dts.push_back(*step);
  }
  return also;
}

void compare_case(CaseResults& results, const KeptResults& kept,
                  const std::optional<Shard>& shard) {
  const Scene& scene = *results.scene;
  std::vector<const RunRecord*> before, now;
  for (const RunRecord& run : kept.runs)
    if (in_shard(shard, scene, run.backend)) before.push_back(&run);
  if (in_shard(shard, scene, results.reference_run.backend)) now.push_back(&results.reference_run);
  for (const RunRecord& run : results.runs)
    if (in_shard(shard, scene, run.backend)) now.push_back(&run);
  results.baseline = compare_with_baseline(before, now, scene.baseline);
}

}  // namespace bb::cli
