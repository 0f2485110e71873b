// The README names the engine versions that `beachball list` reports for the built plugins.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <regex>

#include "support/program.hpp"
#include "support/test_support.hpp"

namespace bb {
namespace {

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
  return s;
}

TEST(Readme, NamesTheEngineVersionsListReports) {
  const test::Outcome list = test::beachball("list");
  ASSERT_EQ(list.exit_code, 0) << list.out;
  std::ifstream in(test::source_path("README.md"));
  const std::string readme = lower(std::string(std::istreambuf_iterator<char>(in), {}));
  // "built (bullet 3.24)": the library and the version its plugin reports.
  const std::regex built(R"(built \(([a-z0-9]+) ([0-9][0-9.]*))");
  int engines = 0;
  for (std::sregex_iterator m(list.out.begin(), list.out.end(), built), end; m != end; ++m) {
    const std::string named = lower((*m)[1].str() + " " + (*m)[2].str());
    EXPECT_NE(readme.find(named), std::string::npos) << "README does not say '" << named << "'";
    ++engines;
  }
  if (engines == 0) GTEST_SKIP() << "no engine plugin is built";
}

}  // namespace
}  // namespace bb
