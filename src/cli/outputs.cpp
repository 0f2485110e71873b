#include <filesystem>

#include "cli/commands.hpp"
#include "report/atomic_file.hpp"
#include "report/csv_writer.hpp"
#include "report/json_writer.hpp"
#include "report/markdown_writer.hpp"

namespace bb::cli {

void write_case_outputs(const CaseResults& results, const std::string& dir) {
  std::filesystem::create_directories(dir);
  const std::string base = (std::filesystem::path(dir) / results.scene->name).string();
  write_file_atomically(base + ".json", results_json(results).dump(2) + "\n");
  write_file_atomically(base + ".csv", results_csv(results));
  const PlotFiles plots = write_plots(results, dir);
  write_file_atomically(base + ".md", results_markdown(results, plots));
}

}  // namespace bb::cli
