// The fuzzer's invariant, replayed on every run: each input of its seed corpus and each
// input it once found troublesome (tests/fuzz_regressions/) loads, or fails as bad input
// with a CaseError; nothing else escapes the loader.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "study/case_error.hpp"
#include "support/test_support.hpp"

namespace bb {
namespace {

TEST(FuzzInvariant, CorpusAndRegressionsLoadOrAreBadInput) {
  int inputs = 0;
  for (const char* folder : {"cases", "tests/cases", "tests/bad_cases", "tests/fuzz_regressions"})
    for (const auto& entry : std::filesystem::directory_iterator(test::source_path(folder))) {
      if (entry.path().filename() == "README.md") continue;
      std::ifstream in(entry.path(), std::ios::binary);
      std::ostringstream text;
      text << in.rdbuf();
      try {
        parse_case(text.str(), entry.path().filename().string());
      } catch (const CaseError&) {
      } catch (const std::exception& e) {
        ADD_FAILURE() << entry.path() << " raised something other than a CaseError: " << e.what();
      }
      ++inputs;
    }
  EXPECT_GE(inputs, 90);
}

}  // namespace
}  // namespace bb
