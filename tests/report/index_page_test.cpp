// The index fits a screen: no table wider than kMaxIndexColumns, whatever the number of cases
// in a section or of backends, and every case still has a cell per backend that links to it.
#include "report/index_page.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <deque>
#include <sstream>

#include "report/format.hpp"
#include "support/test_support.hpp"

namespace bb {
namespace {

/// Cells in a Markdown table row (unescaped '|' count minus one).
int index_row_cells(const std::string& line) {
  int pipes = 0;
  for (std::size_t i = 0; i < line.size(); ++i) {
    if (line[i] == '\\')
      ++i;
    else if (line[i] == '|')
      ++pipes;
  }
  return pipes - 1;
}

/// The widest table row of `page`, in cells.
int widest_table(const std::string& page) {
  std::istringstream lines(page);
  int widest = 0;
  for (std::string line; std::getline(lines, line);)
    if (!line.empty() && line[0] == '|') widest = std::max(widest, index_row_cells(line));
  return widest;
}

TEST(IndexPage, ASectionOfManyCasesAndBackendsKeepsEveryTableNarrow) {
  // 15 cases of one section, 25 backends: one table of them all would be 26 or 17 wide.
  std::deque<Scene> scenes;
  std::vector<CaseResults> all;
  for (int c = 0; c < 15; ++c) {
    scenes.push_back(test::scene_from(test::minimal_case(fmt::format("case{}", c))));
    scenes.back().seed = "7. Springs";
    CaseResults r;
    r.scene = &scenes.back();
    for (int b = 0; b < 25; ++b) {
      RunRecord run;
      run.backend = fmt::format("backend{}", b);
      run.dt = scenes.back().report_dt;
      run.status = RunStatus::Ok;
      run.errors = ErrorMetrics{};
      run.errors->position_max = 0.001 * (c + 1) + b;
      r.runs.push_back(run);
    }
    all.push_back(std::move(r));
  }
  const std::string page = section_tables(all);
  EXPECT_LE(widest_table(page), kMaxIndexColumns) << page;
  // Each case heads one column and is listed once above its table; each backend's cell for
  // it holds its own error.
  for (int c = 0; c < 15; ++c) {
    const std::string link = fmt::format("[case{0}](case{0}.md)", c);
    std::size_t count = 0;
    for (std::size_t at = page.find(link); at != std::string::npos; at = page.find(link, at + 1))
      ++count;
    EXPECT_EQ(count, 2u) << link;
  }
  EXPECT_NE(page.find(fmt::format("{} m", format_value(24.015))), std::string::npos) << page;
}

TEST(IndexPage, TheCommittedIndexFitsAScreen) {
  EXPECT_LE(widest_table(test::bytes(test::source_path("reports/README.md"))), kMaxIndexColumns);
}

}  // namespace
}  // namespace bb
