// Hostile nesting cannot crash the loader: every shape that makes toml++ recurse is refused
// with file and line before the parser sees it, up to the 1 MiB file limit, while strings
// full of brackets and dots still load.
#include "study/toml_depth.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "run/case_loading.hpp"
#include "study/case_error.hpp"
#include "support/program.hpp"
#include "support/test_support.hpp"

namespace bb {
namespace {

std::string repeat(const std::string& part, int times, const std::string& separator = "") {
  std::string out;
  for (int i = 0; i < times; ++i) out += (i ? separator : "") + part;
  return out;
}

/// Each shape, about 70 KB to 1 MiB, on line 3 of an otherwise valid start.
std::vector<std::pair<std::string, std::string>> hostile_shapes() {
  const std::string start = "name = \"deep\"\ndims = 2\n";
  return {
      {"table header", start + "[" + repeat("a", 35000, ".") + "]\n"},
      {"array-of-tables header", start + "[[" + repeat("a", 35000, ".") + "]]\n"},
      {"dotted key", start + repeat("a", 35000, ".") + " = 1\n"},
      {"nested arrays", start + "x = " + repeat("[", 500000) + repeat("]", 500000) + "\n"},
      {"nested inline tables", start + "x = " + repeat("{a=", 250000) + "1" + repeat("}", 250000)},
      {"dotted key in an inline table", start + "x = {" + repeat("b", 60000, ".") + " = 1}\n"},
  };
}

TEST(TomlDepth, EveryRecursiveShapeIsRefusedWithFileAndLine) {
  for (const auto& [shape, text] : hostile_shapes()) {
    ASSERT_LE(text.size(), 1024u * 1024u) << shape;
    try {
      parse_case(text, "deep.toml");
      ADD_FAILURE() << shape << " loaded";
    } catch (const CaseError& e) {
      EXPECT_EQ(e.file(), "deep.toml") << shape;
      EXPECT_EQ(e.line(), 3) << shape << ": " << e.what();
      EXPECT_NE(e.problem().find("no case needs"), std::string::npos) << shape << ": " << e.what();
    }
  }
}

TEST(TomlDepth, TheProgramExitsTwoOnEachInsteadOfCrashing) {
  const std::string dir = test::fresh_dir("toml_depth");
  for (const auto& [shape, text] : hostile_shapes()) {
    const std::string file = test::write_case(dir, "deep.toml", text);
    const test::Outcome o = test::beachball("list " + file);
    EXPECT_EQ(o.exit_code, 2) << shape << "\n" << o.out.substr(0, 300);
    EXPECT_NE(o.out.find("deep.toml:3:"), std::string::npos) << shape;
  }
}

TEST(TomlDepth, BracketsAndDotsInsideStringsAndCommentsAreNotStructure) {
  const std::string brackets = repeat("[{.", 20000);
  EXPECT_NO_THROW(check_toml_depth("title = \"" + brackets + "\"\n# " + brackets +
                                       "\nseed = '''\n" + brackets + "\n'''\nv = 1.5\n",
                                   "ok.toml"));
  // Real nesting within the limits passes; one level more fails.
  EXPECT_NO_THROW(check_toml_depth(
      "x = " + repeat("[", kMaxValueNesting) + repeat("]", kMaxValueNesting), "ok.toml"));
  EXPECT_THROW(check_toml_depth(
                   "x = " + repeat("[", kMaxValueNesting + 1) + repeat("]", kMaxValueNesting + 1),
                   "bad.toml"),
               CaseError);
  EXPECT_NO_THROW(check_toml_depth(repeat("a", kMaxKeyParts, ".") + " = 1\n", "ok.toml"));
  EXPECT_THROW(check_toml_depth(repeat("a", kMaxKeyParts + 1, ".") + " = 1\n", "bad.toml"),
               CaseError);
  // The bundled cases all pass the guard.
  for (const auto& entry : std::filesystem::directory_iterator(test::source_path("cases")))
    EXPECT_NO_THROW(load_case(entry.path().string())) << entry.path();
}

}  // namespace
}  // namespace bb
