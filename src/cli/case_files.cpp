#include <algorithm>
#include <filesystem>

#include "cli/commands.hpp"
#include "run/case_loading.hpp"
#include "study/case_error.hpp"

namespace bb::cli {

namespace {

/// A path relative to the working folder when it lies inside it, so that messages and
/// report pages read "cases/drag_fall.toml" rather than a machine's absolute path.
std::string shortest_name(const std::filesystem::path& path) {
  std::error_code ec;
  const auto relative = std::filesystem::relative(path, std::filesystem::current_path(), ec);
  if (ec || relative.empty() || *relative.begin() == "..") return path.string();
  return relative.string();
}

}  // namespace

std::string bundled_cases_folder() {
  if (const char* env = std::getenv("BEACHBALL_CASES"); env && *env) return env;
  return BEACHBALL_CASES_DIR;
}

std::vector<Scene> load_cases(const std::vector<std::string>& paths) {
  namespace fs = std::filesystem;
  std::vector<std::string> files;
  const std::vector<std::string> roots =
      paths.empty() ? std::vector{bundled_cases_folder()} : paths;
  for (const std::string& p : roots) {
    // A folder stands for every .toml file in it, in name order.
    if (fs::is_directory(p)) {
      std::vector<std::string> found;
      for (const auto& entry : fs::directory_iterator(p))
        if (entry.path().extension() == ".toml") found.push_back(shortest_name(entry.path()));
      std::sort(found.begin(), found.end());
      if (found.empty()) throw CaseError(p, 0, "folder holds no .toml case files");
      files.insert(files.end(), found.begin(), found.end());
    } else {
      files.push_back(p);
    }
  }
  std::vector<Scene> scenes;
  for (const std::string& f : files) {
    Scene s = load_case(f);
    for (const Scene& other : scenes)
      if (other.name == s.name)
        throw CaseError(f, 0, "case name '" + s.name + "' is also used by " + other.file);
    scenes.push_back(std::move(s));
  }
  return scenes;
}

}  // namespace bb::cli
