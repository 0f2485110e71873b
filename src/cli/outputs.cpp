#include "cli/commands.hpp"
#include "report/csv_writer.hpp"
#include "report/gnuplot.hpp"
#include "report/json_writer.hpp"
#include "report/markdown_writer.hpp"
#include "run/interrupt.hpp"

namespace bb::cli {

PlotFiles write_case_outputs(const CaseResults& results, FileBatch& batch) {
  const std::string name = results.scene->name;
  // A signal stops the writing between two files (each plot checks too): the batch, not yet
  // committed, goes with everything in it.
  stop_if_interrupted(name + "'s files");
  batch.write(name + ".json", results_json(results).dump(2) + "\n");
  stop_if_interrupted(name + "'s files");
  batch.write(name + ".csv", results_csv(results));
  const PlotFiles plots = write_plots(results, batch);
  stop_if_interrupted(name + "'s files");
  batch.write(name + ".md", results_markdown(results, plots));
  return plots;
}

KeptDrawings keep_drawings(const RunOptions& options) {
  if (!options.cache) return KeptDrawings(nullptr, false);
  return KeptDrawings(&options.cache->store(), !options.cache->fresh());
}

std::vector<std::string> case_output_names(const Scene& scene) {
  std::vector<std::string> names = plot_file_names(scene);
  for (const char* ext : {".json", ".csv", ".md"}) names.push_back(scene.name + ext);
  return names;
}

}  // namespace bb::cli
