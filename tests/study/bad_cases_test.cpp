// The catalogue of malformed and hostile case files in tests/bad_cases/: each file's first
// line says what it must produce, "# expect: LINE: TEXT" ("-" for no particular line). The
// loader must name the file, that line and that problem; the program must exit 2 and write
// nothing.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <array>
#include <filesystem>
#include <fstream>

#include "study/case_error.hpp"
#include "support/test_support.hpp"

namespace bb {
namespace {

namespace fs = std::filesystem;

struct Expectation {
  std::string file;
  int line = 0;  ///< 0: any
  std::string problem;
};

void PrintTo(const Expectation& e, std::ostream* os) {
  *os << fs::path(e.file).filename().string();
}

std::vector<Expectation> catalogue() {
  std::vector<Expectation> out;
  for (const auto& entry : fs::directory_iterator(test::source_path("tests/bad_cases"))) {
    std::ifstream in(entry.path());
    std::string first;
    std::getline(in, first);
    const std::string prefix = "# expect: ";
    if (first.rfind(prefix, 0) != 0) continue;
    const std::size_t colon = first.find(": ", prefix.size());
    const std::string line = first.substr(prefix.size(), colon - prefix.size());
    out.push_back(
        {entry.path().string(), line == "-" ? 0 : std::stoi(line), first.substr(colon + 2)});
  }
  std::sort(out.begin(), out.end(), [](const auto& a, const auto& b) { return a.file < b.file; });
  return out;
}

class BadCase : public ::testing::TestWithParam<Expectation> {};

TEST_P(BadCase, LoaderNamesFileLineAndProblem) {
  const Expectation& e = GetParam();
  try {
    load_case(e.file);
    FAIL() << "loaded without complaint";
  } catch (const CaseError& error) {
    EXPECT_EQ(error.file(), e.file);
    if (e.line > 0) {
      EXPECT_EQ(error.line(), e.line) << error.what();
    }
    EXPECT_NE(error.problem().find(e.problem), std::string::npos)
        << "message: " << error.what() << "\nexpected: " << e.problem;
  }
}

/// Exit code and combined output of the program.
std::pair<int, std::string> program(const std::string& args) {
  FILE* pipe = popen((std::string(BEACHBALL_PROGRAM) + " " + args + " 2>&1").c_str(), "r");
  std::string out;
  std::array<char, 4096> buffer{};
  while (std::size_t n = fread(buffer.data(), 1, buffer.size(), pipe)) out.append(buffer.data(), n);
  const int status = pclose(pipe);
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, out};
}

TEST_P(BadCase, ProgramExitsTwoAndWritesNothing) {
  const Expectation& e = GetParam();
  const std::string out = ::testing::TempDir() + "/bad_case_out";
  fs::remove_all(out);
  const auto [code, text] = program("run '" + e.file + "' --out " + out + " --no-cost");
  EXPECT_EQ(code, 2) << text;
  const std::string where =
      e.line > 0 ? e.file + ":" + std::to_string(e.line) + ": " : e.file + ":";
  EXPECT_NE(text.find(where), std::string::npos) << text;
  EXPECT_NE(text.find(e.problem), std::string::npos) << text;
  EXPECT_FALSE(fs::exists(out));
}

INSTANTIATE_TEST_SUITE_P(Catalogue, BadCase, ::testing::ValuesIn(catalogue()),
                         [](const auto& info) {
                           return fs::path(info.param.file).stem().string();
                         });

TEST(BadCaseCatalogue, HasAtLeastFortyCases) {
  EXPECT_GE(catalogue().size(), 40u);
}

std::string problem_of(const std::string& path) {
  try {
    load_case(path);
  } catch (const CaseError& e) {
    return e.problem();
  }
  return "no error";
}

TEST(BadFiles, MissingFolderDeviceEmptyAndHuge) {
  EXPECT_EQ(problem_of("/nonexistent/case.toml"), "no such file");
  EXPECT_NE(problem_of(test::source_path("cases")).find("is a directory"), std::string::npos);
  EXPECT_NE(problem_of("/dev/null").find("not a regular file"), std::string::npos);
  const std::string empty = ::testing::TempDir() + "/empty.toml";
  std::ofstream(empty) << "\n  \n";
  EXPECT_NE(problem_of(empty).find("is empty"), std::string::npos);
  // 100 MB, made sparse so the test stays quick; refused before it is read.
  const std::string huge = ::testing::TempDir() + "/huge.toml";
  std::ofstream(huge).close();
  fs::resize_file(huge, 100u << 20);
  EXPECT_NE(problem_of(huge).find("a case file may be at most 1 MiB"), std::string::npos)
      << problem_of(huge);
  const auto [code, text] = program("run " + huge + " --out " + ::testing::TempDir() + "/huge_out");
  EXPECT_EQ(code, 2);
  EXPECT_FALSE(fs::exists(::testing::TempDir() + "/huge_out"));
  fs::remove(huge);
}

}  // namespace
}  // namespace bb
