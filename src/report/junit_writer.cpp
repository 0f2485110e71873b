#include "report/junit_writer.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "report/baseline_text.hpp"
#include "report/format.hpp"
#include "report/xml_text.hpp"

namespace bb {

namespace {

/// One suite's test cases and their counts.
struct Suite {
  std::string cases;
  int tests = 0, failures = 0, skipped = 0;

  /// A test case; `failure` or `skipped` given (not both) when it did not pass.
  void add(const std::string& suite, const std::string& name, const std::string& failure,
           const std::string& skip = "") {
    ++tests;
    cases += fmt::format("    <testcase classname=\"beachball.{}\" name=\"{}\"", suite,
                         escape_xml(name));
    if (failure.empty() && skip.empty()) {
      cases += "/>\n";
      return;
    }
    const bool failed = !failure.empty();
    failures += failed;
    skipped += !failed;
    cases += fmt::format(">\n      <{} message=\"{}\"/>\n    </testcase>\n",
                         failed ? "failure" : "skipped", escape_xml(failed ? failure : skip));
  }
};

void add_gates(const CaseResults& r, Suite& suite) {
  for (const GateResult& g : r.gates) {
    std::string failure;
    if (!g.passed)
      failure = g.value ? fmt::format("{} = {} exceeds max {}", g.gate.metric,
                                      format_value(g.value), format_value(g.gate.max))
                        : g.note;
    // A gate measured against the fallback says so in its name, passed or not.
    suite.add(
        r.scene->name,
        g.gate.backend + " " + g.gate.metric + (g.against.empty() ? "" : " (" + g.against + ")"),
        failure);
  }
}

/// One test case per backend and metric compared with the baseline, over every dt: failed
/// where one got worse (each named), skipped where none could be compared (why).
void add_baseline(const CaseResults& r, Suite& suite) {
  std::vector<std::pair<std::string, std::string>> order;
  for (const BaselineComparison& c : r.baseline) {
    // Nothing to say where neither side had a value (no reference value, diverged in both).
    if (c.change == Change::NothingToCompare) continue;
    const std::pair<std::string, std::string> key{c.backend, c.metric};
    if (std::find(order.begin(), order.end(), key) == order.end()) order.push_back(key);
  }
  for (const auto& [backend, metric] : order) {
    std::string worse, not_compared;
    bool compared = false;
    for (const BaselineComparison& c : r.baseline) {
      if (c.backend != backend || c.metric != metric) continue;
      if (c.change == Change::Worse || c.change == Change::Better || c.change == Change::Unchanged)
        compared = true;
      std::string& into = c.change == Change::Worse ? worse : not_compared;
      into += (into.empty() ? "" : "; ") + change_word(c.change) + ": " + baseline_change_text(c);
    }
    const std::string name = "baseline " + backend + (metric.empty() ? "" : " " + metric);
    suite.add(r.scene->name, name, worse, compared ? "" : not_compared);
  }
}

/// ` skipped="N"` where some test cases were skipped; nothing otherwise.
std::string skipped_attribute(int skipped) {
  return skipped > 0 ? fmt::format(" skipped=\"{}\"", skipped) : "";
}

}  // namespace

std::string junit_xml(const std::vector<CaseResults>& all) {
  int tests = 0, failures = 0, skipped = 0;
  std::string suites;
  for (const CaseResults& r : all) {
    Suite suite;
    add_gates(r, suite);
    add_baseline(r, suite);
    tests += suite.tests;
    failures += suite.failures;
    skipped += suite.skipped;
    suites += fmt::format(
        "  <testsuite name=\"{}\" tests=\"{}\" failures=\"{}\"{}>\n{}  </testsuite>\n",
        r.scene->name, suite.tests, suite.failures, skipped_attribute(suite.skipped), suite.cases);
  }
  return fmt::format(
      "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<testsuites name=\"beachball gates\" "
      "tests=\"{}\" failures=\"{}\"{}>\n{}</testsuites>\n",
      tests, failures, skipped_attribute(skipped), suites);
}

}  // namespace bb
