// docs/case-format.md documents every key the loader accepts, and only those. The loader
// tells an observer of every (table, key) it asks for (TomlReader::observe_keys); loading
// every case of the repository (the suite, the cases written from the format, the bad-case
// catalogue) with one installed collects them; the engines' keys come from the engine
// catalogue. The doc has a heading per section naming it in backticks (`[[body]]`; "Top
// level" for the case's own keys) and, under it, a table whose header's first cell is "key"
// and whose rows give the key in backticks in the first cell.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <map>
#include <set>

#include "docs/doc_tables.hpp"
#include "model/features.hpp"
#include "run/engine_catalogue.hpp"
#include "seam/engine_keys.hpp"
#include "study/case_error.hpp"
#include "study/toml_reader.hpp"

namespace bb {
namespace {

namespace fs = std::filesystem;

const char* kCaseFormatDoc = "docs/case-format.md";

/// Every (table, key) the loader asked for while the observer was installed.
std::set<std::pair<std::string, std::string>>& asked_keys() {
  static std::set<std::pair<std::string, std::string>> keys;
  return keys;
}

void remember_key(const std::string& table, const std::string& key) {
  asked_keys().insert({table, key});
}

/// The observer installed for one scope.
class KeyObserverScope {
 public:
  KeyObserverScope() {
    asked_keys().clear();
    TomlReader::observe_keys(remember_key);
  }
  ~KeyObserverScope() { TomlReader::observe_keys(nullptr); }
};

/// Per section as the loader names it ("the case", "[air]", "[[body]]", "[engines.ode]"),
/// the keys it accepts.
using SectionKeys = std::map<std::string, std::set<std::string>>;

SectionKeys keys_the_loader_accepts() {
  KeyObserverScope observing;
  for (const char* folder : {"cases", "tests/cases", "tests/bad_cases"})
    for (const auto& entry : fs::directory_iterator(test::source_path(folder))) {
      if (entry.path().extension() != ".toml") continue;
      try {
        load_case(entry.path().string());
      } catch (const CaseError&) {
        // A bad case still tells of the keys asked for before its problem.
      }
    }
  std::set<std::string> tables;
  for (const auto& [table, key] : asked_keys()) tables.insert(table);
  SectionKeys accepted;
  for (const auto& [table, key] : asked_keys()) {
    // The engines' tables are checked against the catalogue, which has every key.
    if (table == "[engines]" || table.rfind("[engines.", 0) == 0) continue;
    // A key of the case that is itself a section ([air], [[body]]) is documented as one.
    if (table == "the case") {
      if (key == "engines") continue;
      if (tables.count("[" + key + "]")) {
        accepted["[" + key + "]"];
        continue;
      }
      if (tables.count("[[" + key + "]]")) {
        accepted["[[" + key + "]]"];
        continue;
      }
    }
    accepted[table].insert(key);
  }
  for (const EngineDescription& e : engine_catalogue()) {
    std::set<std::string>& keys = accepted["[engines." + e.engine + "]"];
    for (const EngineKey& k : e.keys) keys.insert(k.key);
  }
  return accepted;
}

/// The section a heading of the doc names: "the case" for "Top level", the first code span
/// when it is a table's name ("[air]", "[[body]]", "[engines.ode]"), else "" (a heading of
/// prose; a name with a placeholder such as `[engines.<engine>]` introduces others).
std::string section_of(const std::string& heading) {
  if (heading == "Top level") return "the case";
  const std::string name = test::first_code_span(heading);
  if (name.empty() || name.front() != '[' || name.find('<') != std::string::npos) return "";
  return name;
}

/// The sections the doc has and the keys their "key" tables list, with the line of each.
struct DocumentedKeys {
  std::map<std::string, int> sections;  ///< section -> line of its heading
  std::map<std::string, std::map<std::string, int>> keys;
};

DocumentedKeys keys_the_doc_lists(const test::DocFile& doc) {
  DocumentedKeys out;
  for (const test::DocHeading& h : doc.headings)
    if (const std::string s = section_of(h.text); !s.empty()) out.sections.emplace(s, h.line);
  for (const test::DocTable& t : doc.tables) {
    if (t.header != "key") continue;
    const std::string s = section_of(t.heading);
    if (s.empty()) {
      ADD_FAILURE() << kCaseFormatDoc << ":" << t.line << ": a key table under the heading '"
                    << t.heading << "', which names no section";
      continue;
    }
    for (const test::DocRow& row : t.rows) {
      if (row.name.empty())
        ADD_FAILURE() << kCaseFormatDoc << ":" << row.line
                      << ": a row of a key table without its key in backticks";
      else
        out.keys[s].emplace(row.name, row.line);
    }
  }
  return out;
}

std::string shown(const std::string& section) {
  return section == "the case" ? "the top level" : section;
}

TEST(CaseFormatDoc, ListsEveryKeyTheLoaderAcceptsAndNoOther) {
  const SectionKeys accepted = keys_the_loader_accepts();
  ASSERT_GT(accepted.size(), 10u) << "the loader told of almost nothing";
  const DocumentedKeys doc = keys_the_doc_lists(test::read_doc_file(kCaseFormatDoc));

  for (const auto& [section, keys] : accepted) {
    if (!doc.sections.count(section)) {
      ADD_FAILURE() << kCaseFormatDoc << " has no section for " << shown(section)
                    << ", which the loader reads: add a heading naming `" << section
                    << "` in backticks, with a table of its keys";
      continue;
    }
    const auto listed = doc.keys.find(section);
    for (const std::string& key : keys)
      if (listed == doc.keys.end() || !listed->second.count(key))
        ADD_FAILURE() << kCaseFormatDoc << ": " << shown(section) << " does not list key '" << key
                      << "', which the loader accepts: add a row `" << key
                      << "` to the key table under that heading";
  }
  for (const auto& [section, line] : doc.sections)
    if (!accepted.count(section))
      ADD_FAILURE() << kCaseFormatDoc << ":" << line << ": section " << section
                    << " is one the loader does not read";
  for (const auto& [section, keys] : doc.keys) {
    const auto known = accepted.find(section);
    for (const auto& [key, line] : keys)
      if (known == accepted.end() || !known->second.count(key))
        ADD_FAILURE() << kCaseFormatDoc << ":" << line << ": " << shown(section) << " lists key '"
                      << key << "', which the loader does not accept";
  }
}

// The observer hears of every key the loader asks for, also of one the case leaves out
// (a default stands in for it), so that no key hides from the test above behind a default.
TEST(CaseFormatDoc, TheLoaderTellsOfKeysACaseLeavesOut) {
  KeyObserverScope observing;
  test::scene_from(test::kMinimalCase);
  for (const auto& [table, key] :
       std::vector<std::pair<std::string, std::string>>{{"the case", "title"},
                                                        {"the case", "seed"},
                                                        {"the case", "gravity"},
                                                        {"[air]", "wind"},
                                                        {"[[body]]", "shape"},
                                                        {"[[body]]", "velocity"},
                                                        {"[course]", "integrators"},
                                                        {"[course]", "spin"}})
    EXPECT_TRUE(asked_keys().count({table, key})) << table << " " << key;
}

/// The prose under the heading `[engines.<engine>]` of the doc, up to its key table.
std::string engine_section_prose(const std::string& doc, const std::string& engine) {
  const std::size_t heading = doc.find("### `[engines." + engine + "]`");
  if (heading == std::string::npos) return "";
  const std::size_t start = doc.find('\n', heading) + 1;
  const std::size_t table = doc.find("\n|", start);
  return doc.substr(start, table == std::string::npos ? std::string::npos : table - start);
}

// Each engine's settings table says which backends read it, and calls no feature
// unsupported that every one of them supports: `[engines.mujoco]` named only `mujoco` and
// still said that body contacts, friction, springs and hinges were unsupported, long after
// the adapter had them.
TEST(CaseFormatDoc, EachEngineTableNamesItsBackendsAndNoSupportedFeatureAsMissing) {
  const std::string doc = test::bytes(test::source_path(kCaseFormatDoc));
  for (const EngineDescription& e : engine_catalogue()) {
    if (!e.has_adapter) continue;
    SCOPED_TRACE(e.engine);
    const std::string prose = engine_section_prose(doc, e.engine);
    ASSERT_FALSE(prose.empty()) << "no section `[engines." << e.engine << "]`";
    for (const EngineVariant& v : e.variants)
      EXPECT_NE(prose.find("`" + v.name + "`"), std::string::npos)
          << "the section does not name backend `" << v.name << "`";
    // A paragraph that calls something unsupported may name only features that some backend
    // of the engine lacks ("body-contact" written "body contact").
    std::string words = prose;
    std::replace(words.begin(), words.end(), '\n', ' ');
    if (words.find("unsupported") == std::string::npos) continue;
    for (Feature f : all_features()) {
      std::string name = feature_name(f);
      std::replace(name.begin(), name.end(), '-', ' ');
      bool all_support = true;
      for (const EngineVariant& v : e.variants) all_support = all_support && v.supports.has(f);
      EXPECT_FALSE(all_support && words.find(name) != std::string::npos)
          << "the section calls '" << name << "' unsupported, and every backend of " << e.engine
          << " supports it";
    }
  }
}

}  // namespace
}  // namespace bb
