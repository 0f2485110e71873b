// docs/architecture.md is the layering rule: a table of folders and the folders each may
// include. Every #include "<folder>/..." in src/ and adapters/ must be allowed by its row,
// and every folder of src/ has a row, so an arrow pointing up fails here.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>

#include "support/test_support.hpp"

namespace bb {
namespace {

namespace fs = std::filesystem;

/// Per folder ("scene", "adapters"), the folders it may include, from the doc's table.
std::map<std::string, std::set<std::string>> allowed_includes() {
  std::ifstream in(test::source_path("docs/architecture.md"));
  std::map<std::string, std::set<std::string>> out;
  const std::regex span("`([a-z_]+)/`");
  std::string line;
  while (std::getline(in, line)) {
    if (line.rfind("| `", 0) != 0) continue;
    // | `folder/` | holds | may include |
    const std::size_t last = line.rfind('|', line.size() - 2);
    std::smatch m;
    if (!std::regex_search(line, m, span)) continue;
    const std::string folder = m[1];
    const std::string may = line.substr(last);
    for (auto it = std::sregex_iterator(may.begin(), may.end(), span); it != std::sregex_iterator();
         ++it)
      out[folder].insert((*it)[1]);
    out[folder].insert(folder);
  }
  return out;
}

/// Each `#include "<folder>/` of a file, with its line.
std::vector<std::pair<std::string, int>> included_folders(const fs::path& file) {
  std::ifstream in(file);
  std::vector<std::pair<std::string, int>> out;
  const std::regex include("^#include \"([a-z_]+)/");
  std::string line;
  for (int n = 1; std::getline(in, line); ++n) {
    std::smatch m;
    if (std::regex_search(line, m, include)) out.emplace_back(m[1], n);
  }
  return out;
}

TEST(Architecture, EveryIncludeInSrcAndAdaptersPointsDownAsTheDocSays) {
  const auto allowed = allowed_includes();
  ASSERT_GE(allowed.size(), 10u) << "docs/architecture.md lost its table";
  // Every folder of src/ has a row.
  for (const auto& entry : fs::directory_iterator(test::source_path("src"))) {
    if (!entry.is_directory()) continue;
    EXPECT_TRUE(allowed.count(entry.path().filename().string()))
        << "docs/architecture.md has no row for src/" << entry.path().filename().string();
  }
  int checked = 0;
  for (const char* root : {"src", "adapters"})
    for (const auto& entry : fs::recursive_directory_iterator(test::source_path(root))) {
      const std::string ext = entry.path().extension().string();
      if (ext != ".cpp" && ext != ".hpp" && ext != ".in") continue;
      const std::string folder =
          std::string(root) == "adapters"
              ? "adapters"
              : fs::relative(entry.path(), test::source_path("src")).begin()->string();
      const auto rule = allowed.find(folder);
      if (rule == allowed.end()) continue;  // reported above
      for (const auto& [included, line] : included_folders(entry.path())) {
        ++checked;
        EXPECT_TRUE(rule->second.count(included))
            << entry.path().string() << ":" << line << ": " << folder << "/ includes " << included
            << "/, which docs/architecture.md does not allow";
      }
    }
  EXPECT_GT(checked, 100);
}

}  // namespace
}  // namespace bb
