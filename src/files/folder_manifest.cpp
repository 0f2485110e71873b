#include "files/folder_manifest.hpp"

#include <filesystem>
#include <fstream>

namespace bb {

namespace fs = std::filesystem;

namespace {

constexpr const char* kManifestHeading =
    "# beachball wrote these files here; it replaces or removes only the files listed\n";

}  // namespace

std::set<std::string> read_manifest(const std::string& folder) {
  std::set<std::string> names;
  std::ifstream in(folder + "/" + kManifestName);
  std::string line;
  while (std::getline(in, line))
    if (!line.empty() && line[0] != '#' && line.find('/') == std::string::npos) names.insert(line);
  return names;
}

bool has_manifest(const std::string& folder) {
  std::error_code ec;
  return fs::is_regular_file(fs::symlink_status(folder + "/" + kManifestName, ec));
}

std::string manifest_text(const std::set<std::string>& names) {
  std::string text = kManifestHeading;
  for (const std::string& name : names) text += name + "\n";
  return text;
}

bool holds_only_recorded_files(const std::string& folder, std::string* foreign) {
  if (foreign) foreign->clear();
  std::error_code ec;
  if (!fs::is_directory(fs::symlink_status(folder, ec)) || !has_manifest(folder)) return false;
  const std::set<std::string> listed = read_manifest(folder);
  std::set<std::string> unlisted;
  for (const auto& entry : fs::directory_iterator(folder, ec)) {
    const std::string name = entry.path().filename().string();
    if (name == kManifestName) continue;
    std::error_code kind_error;
    if (!listed.count(name) || !fs::is_regular_file(entry.symlink_status(kind_error)))
      unlisted.insert(name);
  }
  if (ec) return false;
  if (foreign && !unlisted.empty()) *foreign = *unlisted.begin();
  return unlisted.empty();
}

bool earlier_report(const std::string& folder) {
  std::ifstream readme(folder + "/README.md");
  std::string first;
  if (!std::getline(readme, first) || first != "# beachball report") return false;
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(folder, ec)) {
    const std::string ext = entry.path().extension().string();
    std::error_code kind_error;
    if (!entry.is_regular_file(kind_error) || entry.is_symlink(kind_error)) return false;
    if (ext != ".md" && ext != ".json" && ext != ".csv" && ext != ".svg") return false;
  }
  return !ec;
}

}  // namespace bb
