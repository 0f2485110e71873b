#include "report/junit_writer.hpp"

#include <fmt/format.h>

#include "report/format.hpp"
#include "report/xml_text.hpp"

namespace bb {

std::string junit_xml(const std::vector<CaseResults>& all) {
  int tests = 0, failures = 0;
  std::string suites;
  for (const CaseResults& r : all) {
    int suite_failures = 0;
    std::string cases;
    for (const GateResult& g : r.gates) {
      const std::string name = g.gate.backend + " " + g.gate.metric;
      cases += fmt::format("    <testcase classname=\"beachball.{}\" name=\"{}\"", r.scene->name,
                           escape_xml(name));
      if (g.passed) {
        cases += "/>\n";
        continue;
      }
      ++suite_failures;
      const std::string message = g.value
                                      ? fmt::format("{} = {} exceeds max {}", g.gate.metric,
                                                    format_value(g.value), format_value(g.gate.max))
                                      : g.note;
      cases +=
          fmt::format(">\n      <failure message=\"{}\"/>\n    </testcase>\n", escape_xml(message));
    }
    tests += static_cast<int>(r.gates.size());
    failures += suite_failures;
    suites +=
        fmt::format("  <testsuite name=\"{}\" tests=\"{}\" failures=\"{}\">\n{}  </testsuite>\n",
                    r.scene->name, r.gates.size(), suite_failures, cases);
  }
  return fmt::format(
      "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<testsuites name=\"beachball gates\" "
      "tests=\"{}\" failures=\"{}\">\n{}</testsuites>\n",
      tests, failures, suites);
}

}  // namespace bb
