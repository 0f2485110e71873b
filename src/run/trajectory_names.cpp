#include "run/trajectory_names.hpp"

#include <algorithm>
#include <map>
#include <sstream>

#include "model/text.hpp"
#include "study/case_error.hpp"

namespace bb {

namespace {

/// `text` with every '/' written '-': a file name holds no '/'.
std::string without_slashes(std::string text) {
  std::replace(text.begin(), text.end(), '/', '-');
  return text;
}

/// The line of the case's top-level key `dt` in its text (the keys before the first table),
/// or 0 when the case has no text (made in code).
int dt_line(const std::string& source) {
  std::istringstream lines(source);
  int number = 0;
  for (std::string line; std::getline(lines, line);) {
    ++number;
    const std::size_t at = line.find_first_not_of(" \t");
    if (at == std::string::npos) continue;
    if (line[at] == '[') break;
    const std::size_t after = line.find_first_not_of(" \t", at + 2);
    if (line.compare(at, 2, "dt") == 0 && after != std::string::npos && line[after] == '=')
      return number;
  }
  return 0;
}

}  // namespace

std::string trajectory_folder_name(const std::string& case_name) {
  return case_name + "-trajectories";
}

std::string trajectory_file_name(const std::string& backend, std::optional<double> dt) {
  if (!dt) return "reference.csv";
  return without_slashes(backend) + "@" + without_slashes(format_dt(*dt)) + ".csv";
}

void check_trajectory_names(const Scene& scene) {
  std::map<std::string, double> seen;
  for (double dt : scene.dt) {
    const auto [at, added] = seen.emplace(trajectory_file_name("", dt), dt);
    if (!added)
      throw CaseError(scene.file, dt_line(scene.source),
                      "dt: the steps " + exact_number(at->second) + " and " + exact_number(dt) +
                          " would both write the trajectory files named '<backend>" + at->first +
                          "' (--trajectories names a run's file by its step as the table shows "
                          "it); make them differ within 6 significant digits");
  }
}

}  // namespace bb
