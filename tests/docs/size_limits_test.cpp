// No file over 400 lines and no function over 80 (issue 40, item 5): every .cpp and .hpp of
// src/, adapters/, tests/, bench/, sdk/ and docs/examples/ is read, and each file or
// function past its limit fails with its file:line and its count. What the scanner counts
// as a function and its lines (tests/support/source_spans.hpp): a brace opened where
// declarations stand after a head with a parameter list and no `=` (free and member
// functions, constructors, operators, TEST/TEST_F/TEST_P bodies), from its head's first line
// to its closing brace; namespaces, classes, structs, unions, enums and initializer tables
// are not functions, and braces in comments, literals and preprocessor lines count for
// nothing. The first tests hold the scanner to that on small texts.
#include <gtest/gtest.h>

#include <filesystem>

#include "support/source_spans.hpp"
#include "support/test_support.hpp"

namespace bb {
namespace {

namespace fs = std::filesystem;

constexpr int kFileLimit = 400;
constexpr int kFunctionLimit = 80;

/// `count` lines of one statement each, for a body of a known length.
std::string statements(int count) {
  std::string out;
  for (int i = 0; i < count; ++i) out += "  x += " + std::to_string(i) + ";\n";
  return out;
}

/// The spans found, as "name first_line lines" for a readable comparison.
std::vector<std::string> spans_of(const std::string& text) {
  std::vector<std::string> out;
  for (const test::FunctionSpan& f : test::function_spans(text))
    out.push_back(f.name + " " + std::to_string(f.first_line) + " " + std::to_string(f.lines));
  return out;
}

TEST(SizeLimits, AFunctionRunsFromItsHeadToItsClosingBrace) {
  // A free function, a TEST body and a signature over two lines, inside namespaces.
  const std::string text = "namespace a {\nnamespace {\n\nint f(int x) {\n" + statements(5) +
                           "  return x;\n}\n\nTEST(Suite, Name) {\n" + statements(2) +
                           "}\n\nstatic int g(int a,\n              int b) { return a + b; }\n"
                           "}  // namespace\n}  // namespace a\n";
  EXPECT_EQ(spans_of(text),
            (std::vector<std::string>{"f 4 8", "TEST(Suite, Name) 13 4", "g 18 2"}));
}

TEST(SizeLimits, MembersAreFunctionsButTheirClassIsNot) {
  // A class, its inline members (after an access label and a template line), a constructor
  // with braced member initializers, an operator, and a member of a nested struct.
  const std::string text =
      "class C : public B {\n public:\n  C(int a) : a_{a}, b_(a) {\n    x();\n  }\n"
      "  template <typename T>\n  T get() const {\n    return T{};\n  }\n"
      "  bool operator()(int) const { return true; }\n\n private:\n"
      "  struct Inner {\n    void h() {}\n  };\n  int a_, b_;\n};\n"
      "C::~C() {\n}\n";
  EXPECT_EQ(spans_of(text), (std::vector<std::string>{"C 3 3", "get 7 3", "operator() 10 1",
                                                      "h 14 1", "C::~C 18 2"}));
}

TEST(SizeLimits, TablesEnumsAndInitializersAreNotFunctions) {
  // A table of a hundred rows, an enum, a braced constant, a lambda bound to a name, and a
  // function whose default argument is braced: only the last is a function.
  std::string table = "const std::vector<Row> kRows = {\n";
  for (int i = 0; i < 100; ++i) table += "    {\"row\", " + std::to_string(i) + "},\n";
  const std::string text = table + "};\nenum class E {\n  kA,\n  kB,\n};\n" +
                           "constexpr Cap kCap{\n    1.0, 2.0};\n" +
                           "const auto kLambda = [](int v) {\n" + statements(90) + "};\n" +
                           "int f(Options o = {}) {\n  return 0;\n}\n";
  EXPECT_EQ(spans_of(text), (std::vector<std::string>{"f 201 3"}));
}

TEST(SizeLimits, BracesInCommentsLiteralsAndDirectivesCountForNothing) {
  // Every stray brace sits in a comment, a string, a character, a raw string with a
  // delimiter, or a macro; and a digit separator is not a character literal.
  const std::string text =
      "// } {\n/* {\n } */\n#define OPEN {\n#define TWO \\\n  }\n"
      "int f() {\n  const char* s = \"}\\\"{\";\n  char c = '}';\n"
      "  const char* r = R\"toml([a]\nb = { c = 1 }\n)\" }\n)toml\";\n  int n = 1'000;\n"
      "  return n;\n}\nint g() { return 0; }\n";
  EXPECT_EQ(spans_of(text), (std::vector<std::string>{"f 7 10", "g 17 1"}));
}

TEST(SizeLimits, AFileCountsItsLastLineWithOrWithoutANewline) {
  EXPECT_EQ(test::line_count(""), 0);
  EXPECT_EQ(test::line_count("a\nb\n"), 2);
  EXPECT_EQ(test::line_count("a\nb"), 2);
}

TEST(SizeLimits, NoFileOver400LinesAndNoFunctionOver80) {
  int files = 0, functions = 0;
  for (const char* root : {"src", "adapters", "tests", "bench", "sdk", "docs/examples"})
    for (const auto& entry : fs::recursive_directory_iterator(test::source_path(root))) {
      const std::string ext = entry.path().extension().string();
      if (!entry.is_regular_file() || (ext != ".cpp" && ext != ".hpp")) continue;
      ++files;
      const std::string text = test::bytes(entry.path());
      const std::string name = fs::relative(entry.path(), test::source_path("")).string();
      EXPECT_LE(test::line_count(text), kFileLimit)
          << name << ":1: the file has " << test::line_count(text) << " lines (limit " << kFileLimit
          << "): split it by the idea each part holds";
      for (const test::FunctionSpan& f : test::function_spans(text)) {
        ++functions;
        EXPECT_LE(f.lines, kFunctionLimit)
            << name << ":" << f.first_line << ": " << f.name << " has " << f.lines
            << " lines (limit " << kFunctionLimit << "): split it into named parts";
      }
    }
  // The scanner read the tree: hundreds of files, thousands of functions.
  EXPECT_GT(files, 400);
  EXPECT_GT(functions, 2000);
}

}  // namespace
}  // namespace bb
