// The README names the engine versions that `beachball list` reports for the built plugins.
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <fstream>

#include "support/missing.hpp"
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
  // "built (bullet 3.24)": the library and the version its plugin reports. (Parsed by hand:
  // std::regex trips GCC 12's maybe-uninitialized warning in the sanitizer build.)
  const std::string marker = "built (";
  int engines = 0;
  for (std::size_t at = list.out.find(marker); at != std::string::npos;
       at = list.out.find(marker, at + 1)) {
    const std::size_t start = at + marker.size();
    const std::size_t space = list.out.find(' ', start);
    std::size_t end = space + 1;
    while (end < list.out.size() &&
           (std::isdigit(static_cast<unsigned char>(list.out[end])) || list.out[end] == '.'))
      ++end;
    const std::string named = lower(list.out.substr(start, end - start));
    EXPECT_NE(readme.find(named), std::string::npos) << "README does not name '" << named << "'";
    ++engines;
  }
  BB_SKIP_IF_MISSING(engines == 0 ? "no engine plugin is built" : "");
}

}  // namespace
}  // namespace bb
