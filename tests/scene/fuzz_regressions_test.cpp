// Inputs the fuzzer once found troublesome load cleanly or fail as bad input.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "scene/case_error.hpp"
#include "support/test_support.hpp"

namespace bb {
namespace {

TEST(FuzzRegressions, EveryKeptInputLoadsOrIsBadInput) {
  int inputs = 0;
  for (const auto& entry :
       std::filesystem::directory_iterator(test::source_path("tests/fuzz_regressions"))) {
    if (entry.path().filename() == "README.md") continue;
    std::ifstream in(entry.path(), std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    try {
      parse_case(text.str(), entry.path().filename().string());
    } catch (const CaseError&) {
    }
    ++inputs;
  }
  SUCCEED() << inputs << " inputs";
}

}  // namespace
}  // namespace bb
