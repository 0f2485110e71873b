// A case page built from hostile text, the kind a case file's title or an engine's crash
// message can hold, keeps every table whole and holds no HTML from that text.
#include <gtest/gtest.h>

#include <sstream>

#include "report/markdown_writer.hpp"
#include "support/test_support.hpp"

namespace bb {
namespace {

const char* kHostile = "a | b\n<script>alert(1)</script> & c\r\nd";

/// Unescaped '|' in `line`, as GitHub's Markdown counts them.
int pipes_in(const std::string& line) {
  int pipes = 0;
  for (std::size_t i = 0; i < line.size(); ++i) {
    if (line[i] == '\\')
      ++i;
    else if (line[i] == '|')
      ++pipes;
  }
  return pipes;
}

TEST(MarkdownPage, HostileTitleSeedAndReasonsBreakNoTableAndAddNoHtml) {
  Scene scene = test::scene_from(test::kMinimalCase);
  scene.title = kHostile;
  scene.seed = kHostile;
  CaseResults results;
  results.scene = &scene;
  results.reference_run.backend = "reference";
  RunRecord crashed;
  crashed.backend = "course/rk4";
  crashed.dt = scene.report_dt;
  crashed.status = RunStatus::Crashed;
  crashed.reason = kHostile;
  results.runs.push_back(crashed);
  StabilityResult stability;
  stability.backend = "course/rk4";
  stability.status = "unsupported";
  stability.reason = kHostile;
  results.stability.push_back(stability);

  const std::string page = results_markdown(results, PlotFiles{});
  EXPECT_EQ(page.find("<script"), std::string::npos) << page;
  EXPECT_EQ(page.rfind("# a \\| b &lt;script&gt;alert(1)&lt;/script&gt; &amp; c d\n", 0), 0u)
      << page;
  // Within each table (a run of lines starting with '|'), every line has as many cells as
  // the header.
  std::istringstream lines(page);
  int header_pipes = 0, tables = 0;
  for (std::string line; std::getline(lines, line);) {
    if (line.empty() || line[0] != '|') {
      header_pipes = 0;
      continue;
    }
    if (header_pipes == 0) {
      header_pipes = pipes_in(line);
      ++tables;
    }
    EXPECT_EQ(pipes_in(line), header_pipes) << line;
  }
  EXPECT_GE(tables, 4);
}

}  // namespace
}  // namespace bb
