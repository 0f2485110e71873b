// A Markdown table keeps its shape whatever its cells hold: every line has one cell per
// header, and the table has one line per row.
#include "report/table.hpp"

#include <gtest/gtest.h>

#include <sstream>

namespace bb {
namespace {

/// The lines of `text`.
std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) out.push_back(line);
  return out;
}

/// Cells of one table line as GitHub's Markdown splits it: at each '|' that a backslash
/// does not escape (a backslash escapes the character after it, a backslash included).
int cells_in(const std::string& line) {
  int pipes = 0;
  for (std::size_t i = 0; i < line.size(); ++i) {
    if (line[i] == '\\')
      ++i;
    else if (line[i] == '|')
      ++pipes;
  }
  return pipes - 1;
}

TEST(MarkdownTable, HostileCellsKeepEveryRowAtItsColumnCount) {
  Table t;
  t.headers = {"body", "a|header", "note"};
  t.right_aligned = {false, true, false};
  t.rows = {{"ball", "1.5", "plain"},
            {"a|b", "x\\|y", "two\nlines\r\nand\rmore"},
            {"<img src=x onerror=alert(1)>", "&amp;", "end\\"},
            {"short row"}};
  const std::string md = render_markdown(t);
  const auto lines = lines_of(md);
  // Header, separator, and one line per row.
  ASSERT_EQ(lines.size(), 2 + t.rows.size()) << md;
  for (const std::string& line : lines) EXPECT_EQ(cells_in(line), 3) << line;
  EXPECT_EQ(md.find('<'), std::string::npos) << md;
  EXPECT_NE(md.find("&lt;img src=x onerror=alert(1)&gt;"), std::string::npos) << md;
  EXPECT_NE(md.find("a\\|b"), std::string::npos) << md;
  EXPECT_NE(md.find("two lines and more"), std::string::npos) << md;
}

}  // namespace
}  // namespace bb
