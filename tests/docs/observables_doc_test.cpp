// docs/observables.md has a row for every observable kind and every error metric the loader
// accepts, and for no other: a table whose header's first cell is "kind" (or "metric") and
// whose rows name one each in backticks.
#include <gtest/gtest.h>

#include <map>
#include <set>

#include "docs/doc_tables.hpp"
#include "observe/observable_registry.hpp"
#include "study/metric_names.hpp"

namespace bb {
namespace {

const char* kObservablesDoc = "docs/observables.md";

/// The names in the rows of the doc's tables headed `header`, with their lines.
std::map<std::string, int> rows_headed(const std::string& header) {
  std::map<std::string, int> out;
  for (const test::DocTable& t : test::read_doc_file(kObservablesDoc).tables)
    if (t.header == header)
      for (const test::DocRow& row : t.rows) out.emplace(row.name, row.line);
  return out;
}

void expect_same(const std::string& header, const std::vector<std::string>& known) {
  const std::map<std::string, int> documented = rows_headed(header);
  const std::set<std::string> accepted(known.begin(), known.end());
  for (const std::string& name : accepted)
    EXPECT_TRUE(documented.count(name)) << kObservablesDoc << " has no row for the " << header
                                        << " '" << name << "', which the loader accepts: add `"
                                        << name << "` to the table headed '" << header << "'";
  for (const auto& [name, line] : documented)
    EXPECT_TRUE(accepted.count(name)) << kObservablesDoc << ":" << line << ": the " << header
                                      << " '" << name << "' is not one the loader accepts";
}

TEST(ObservablesDoc, HasARowForEveryKind) {
  expect_same("kind", observable_kinds());
}

TEST(ObservablesDoc, HasARowForEveryErrorMetric) {
  expect_same("metric", error_metric_names());
}

}  // namespace
}  // namespace bb
