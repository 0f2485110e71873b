// docs/case-format.md lists every key the loader's source reads, also of a section no case
// uses yet: the coverage test in case_format_doc_test.cpp hears only of the keys the cases it
// loads lead the loader to, so a new sub-table that no case has would go undocumented there.
// This test reads the loader's source instead: every key given as a literal to a TomlReader
// call (`r.number("mass")`, `r.tables("body")`) must be a documented key or section.
#include <gtest/gtest.h>

#include <filesystem>
#include <set>
#include <string>
#include <vector>

#include "docs/doc_tables.hpp"
#include "support/test_support.hpp"

namespace bb {
namespace {

namespace fs = std::filesystem;

/// The TomlReader calls whose first argument is a key of the table being read.
const std::vector<std::string> kKeyReads = {
    "number", "number_or", "integer", "integer_or", "boolean_or", "string", "string_or",
    "vec3",   "vec3_or",   "numbers", "strings",    "strings_or", "table",  "tables"};

/// Every literal key in `source` given to one of kKeyReads: the text between the quotes of
/// `.<call>("<key>"`.
std::set<std::string> literal_keys(const std::string& source) {
  std::set<std::string> keys;
  for (const std::string& call : kKeyReads) {
    const std::string opening = "." + call + "(\"";
    for (std::size_t at = source.find(opening); at != std::string::npos;
         at = source.find(opening, at + 1)) {
      const std::size_t start = at + opening.size();
      const std::size_t end = source.find('"', start);
      if (end != std::string::npos) keys.insert(source.substr(start, end - start));
    }
  }
  return keys;
}

/// The loader's source files: every load_*.cpp under src/.
std::vector<fs::path> loader_sources() {
  std::vector<fs::path> files;
  for (const auto& entry : fs::recursive_directory_iterator(test::source_path("src")))
    if (entry.path().extension() == ".cpp" &&
        entry.path().filename().string().rfind("load_", 0) == 0)
      files.push_back(entry.path());
  return files;
}

/// Every key the doc's key tables list, and every section its headings name.
std::set<std::string> documented_names(const test::DocFile& doc) {
  std::set<std::string> names;
  for (const test::DocTable& t : doc.tables)
    if (t.header == "key")
      for (const test::DocRow& row : t.rows) names.insert(row.name);
  for (const test::DocHeading& h : doc.headings)
    if (const std::string span = test::first_code_span(h.text); !span.empty()) names.insert(span);
  return names;
}

TEST(CaseFormatDoc, EveryKeyTheLoaderSourceReadsIsDocumented) {
  const std::set<std::string> documented =
      documented_names(test::read_doc_file("docs/case-format.md"));
  const std::vector<fs::path> sources = loader_sources();
  ASSERT_GE(sources.size(), 5u) << "the loader's source files were not found under src/";
  std::size_t keys_seen = 0;
  for (const fs::path& file : sources)
    for (const std::string& key : literal_keys(test::bytes(file))) {
      ++keys_seen;
      // A table of tables ([engines.<engine>]) is documented by its members' headings.
      const auto member = documented.lower_bound("[" + key + ".");
      const bool known = documented.count(key) || documented.count("[" + key + "]") ||
                         documented.count("[[" + key + "]]") ||
                         (member != documented.end() && member->rfind("[" + key + ".", 0) == 0);
      EXPECT_TRUE(known) << file.filename().string() << " reads key '" << key
                         << "', which docs/case-format.md lists in no key table or heading";
    }
  EXPECT_GT(keys_seen, 50u) << "the scan found almost no keys: has the reader's interface changed?";
}

}  // namespace
}  // namespace bb
