// docs/output-files.md names, for a trajectory with rows at the samples only, exactly the
// observable kinds that need a run's every step (kReadsSteps in the observables' registry):
// the list a user reads is the list the program applies.
#include <gtest/gtest.h>

#include <set>

#include "observe/observable_registry.hpp"
#include "support/test_support.hpp"

namespace bb {
namespace {

/// The `kinds` in backticks in the paragraph of docs/output-files.md about rows at the
/// samples only, from "say `not measured" to the closing parenthesis.
std::set<std::string> kinds_named_for_samples() {
  const std::string doc = test::bytes(test::source_path("docs/output-files.md"));
  const std::size_t start = doc.find("the trajectory has rows at the samples only`: the");
  const std::size_t end = doc.find("(contacts, apexes", start);
  std::set<std::string> out;
  if (start == std::string::npos || end == std::string::npos) return out;
  for (std::size_t at = doc.find('`', start + 50); at < end; at = doc.find('`', at + 1)) {
    const std::size_t close = doc.find('`', at + 1);
    out.insert(doc.substr(at + 1, close - at - 1));
    at = close;
  }
  return out;
}

TEST(SamplesOnlyDoc, NamesExactlyTheKindsThatNeedTheSteps) {
  std::set<std::string> needing;
  for (const ObservableKind& k : observable_kind_table())
    if (k.needs & kReadsSteps) needing.insert(k.name);
  EXPECT_FALSE(needing.empty());
  EXPECT_EQ(kinds_named_for_samples(), needing);
}

}  // namespace
}  // namespace bb
