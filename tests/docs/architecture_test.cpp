// docs/architecture.md is the layering rule: a table of folders and the folders each may
// include. Every #include "<folder>/..." in src/ and adapters/ must be allowed by its row,
// and every folder of src/ has a row, so an arrow pointing up fails here.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include "support/test_support.hpp"

namespace bb {
namespace {

namespace fs = std::filesystem;

bool is_folder_char(char c) {
  return (c >= 'a' && c <= 'z') || c == '_';
}

/// Every `name/` span of a text, in order (plain parsing: std::regex trips GCC 12's
/// maybe-uninitialized warning in optimised unity builds).
std::vector<std::string> folder_spans(const std::string& text) {
  std::vector<std::string> out;
  for (std::size_t open = text.find('`'); open != std::string::npos;) {
    std::size_t end = open + 1;
    while (end < text.size() && is_folder_char(text[end])) ++end;
    if (end > open + 1 && end + 1 < text.size() && text[end] == '/' && text[end + 1] == '`') {
      out.push_back(text.substr(open + 1, end - open - 1));
      open = text.find('`', end + 2);
    } else {
      open = text.find('`', open + 1);
    }
  }
  return out;
}

/// Per folder ("scene", "adapters"), the folders it may include, from the doc's table.
std::map<std::string, std::set<std::string>> allowed_includes() {
  std::ifstream in(test::source_path("docs/architecture.md"));
  std::map<std::string, std::set<std::string>> out;
  std::string line;
  while (std::getline(in, line)) {
    if (line.rfind("| `", 0) != 0) continue;
    // | `folder/` | holds | may include |
    const std::size_t last = line.rfind('|', line.size() - 2);
    const auto named = folder_spans(line.substr(0, line.find('|', 2)));
    if (named.empty()) continue;
    const std::string& folder = named.front();
    for (const std::string& may : folder_spans(line.substr(last))) out[folder].insert(may);
    out[folder].insert(folder);
  }
  return out;
}

/// Each `#include "<folder>/` of a file, with its line.
std::vector<std::pair<std::string, int>> included_folders(const fs::path& file) {
  std::ifstream in(file);
  std::vector<std::pair<std::string, int>> out;
  const std::string include = "#include \"";
  std::string line;
  for (int n = 1; std::getline(in, line); ++n) {
    if (line.rfind(include, 0) != 0) continue;
    std::size_t end = include.size();
    while (end < line.size() && is_folder_char(line[end])) ++end;
    if (end > include.size() && end < line.size() && line[end] == '/')
      out.emplace_back(line.substr(include.size(), end - include.size()), n);
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

// The model, the seam and the study are separate layers: the model includes only itself,
// the seam only the model, and nothing an engine plugin compiles (the seam, the force model,
// contact pairs, the adapters) sees the study, whose loader links the TOML library.
TEST(Architecture, TheModelTheSeamAndTheStudyAreLayersNoPluginSees) {
  const auto allowed = allowed_includes();
  ASSERT_TRUE(allowed.count("model") && allowed.count("seam") && allowed.count("study"))
      << "docs/architecture.md has no row for model/, seam/ or study/";
  EXPECT_EQ(allowed.at("model"), std::set<std::string>{"model"});
  EXPECT_EQ(allowed.at("seam"), (std::set<std::string>{"model", "seam"}));
  EXPECT_TRUE(allowed.at("study").count("model"));
  for (const char* below_study : {"model", "seam", "physics", "contact", "adapters"}) {
    ASSERT_TRUE(allowed.count(below_study)) << below_study;
    EXPECT_FALSE(allowed.at(below_study).count("study"))
        << below_study << "/ may include study/ in docs/architecture.md";
  }
}

}  // namespace
}  // namespace bb
