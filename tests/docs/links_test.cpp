// The README and docs/ link only to what the repository holds: every relative link names a
// file or folder inside it, and every #anchor a heading of the page it points to (GitHub's
// rule: lower case, punctuation dropped, spaces as hyphens). No page points its readers at
// a design document outside the repository.
#include <gtest/gtest.h>

#include <cctype>
#include <filesystem>
#include <set>

#include "docs/doc_tables.hpp"

namespace bb {
namespace {

namespace fs = std::filesystem;

/// README.md and every page under docs/, relative to the source tree.
std::vector<std::string> pages() {
  std::vector<std::string> out = {"README.md"};
  for (const auto& entry : fs::recursive_directory_iterator(test::source_path("docs")))
    if (entry.path().extension() == ".md")
      out.push_back(fs::relative(entry.path(), test::source_path("")).string());
  return out;
}

/// The anchor GitHub gives a heading.
std::string anchor_of(const std::string& heading) {
  std::string out;
  for (unsigned char c : heading) {
    if (std::isalnum(c) || c == '-' || c == '_' || c >= 0x80)
      out += static_cast<char>(std::tolower(c));
    else if (c == ' ')
      out += '-';
  }
  return out;
}

std::set<std::string> anchors_of(const std::string& page) {
  std::set<std::string> out;
  for (const test::DocHeading& h : test::read_doc_file(page).headings)
    out.insert(anchor_of(h.text));
  return out;
}

struct Link {
  std::string target;
  int line = 0;
};

/// Every inline link `](target)` outside fenced code.
std::vector<Link> links_of(const std::string& text) {
  std::vector<Link> out;
  bool in_fence = false;
  int number = 0;
  std::size_t start = 0;
  while (start < text.size()) {
    const std::size_t end = std::min(text.find('\n', start), text.size());
    const std::string line = text.substr(start, end - start);
    start = end + 1;
    ++number;
    if (line.rfind("```", 0) == 0) in_fence = !in_fence;
    if (in_fence) continue;
    for (std::size_t at = line.find("]("); at != std::string::npos; at = line.find("](", at + 1)) {
      const std::size_t close = line.find(')', at + 2);
      if (close != std::string::npos) out.push_back({line.substr(at + 2, close - at - 2), number});
    }
  }
  return out;
}

TEST(DocLinks, EveryRelativeLinkAndAnchorExists) {
  const fs::path root = fs::weakly_canonical(test::source_path(""));
  int checked = 0;
  for (const std::string& page : pages()) {
    const std::string text = test::bytes(test::source_path(page));
    for (const Link& link : links_of(text)) {
      if (link.target.rfind("http://", 0) == 0 || link.target.rfind("https://", 0) == 0) continue;
      const std::size_t hash = link.target.find('#');
      const std::string file = link.target.substr(0, hash);
      const std::string anchor = hash == std::string::npos ? "" : link.target.substr(hash + 1);
      const fs::path from = fs::path(test::source_path(page)).parent_path();
      const fs::path target =
          fs::weakly_canonical(file.empty() ? test::source_path(page) : (from / file).string());
      const std::string where = page + ":" + std::to_string(link.line) + ": ";
      const std::string inside = fs::relative(target, root).string();
      if (inside.empty() || inside.rfind("..", 0) == 0) {
        ADD_FAILURE() << where << "'" << link.target << "' points outside the repository";
        continue;
      }
      if (!fs::exists(target)) {
        ADD_FAILURE() << where << "'" << link.target << "' names nothing in the repository";
        continue;
      }
      if (!anchor.empty() && target.extension() == ".md" && !anchors_of(inside).count(anchor))
        ADD_FAILURE() << where << "'" << link.target << "': " << inside
                      << " has no heading with the anchor #" << anchor;
      ++checked;
    }
  }
  EXPECT_GT(checked, 20) << "the pages link almost nowhere";
}

TEST(DocLinks, NoPagePointsAtADesignDocumentOutsideTheRepository) {
  for (const std::string& page : pages()) {
    const std::string text = test::bytes(test::source_path(page));
    for (const char* outside : {"DESIGN.md", "../shared", "/work/"})
      EXPECT_EQ(text.find(outside), std::string::npos)
          << page << " mentions " << outside << "; the repository's own design is docs/design.md";
  }
}

}  // namespace
}  // namespace bb
