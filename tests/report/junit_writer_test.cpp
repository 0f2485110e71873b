// The gates as JUnit XML: a suite per case with its counts, a failure that says what was
// measured against which limit, and a backend's name with XML's reserved characters escaped.
#include "report/junit_writer.hpp"

#include <gtest/gtest.h>

namespace bb {
namespace {

TEST(JunitWriter, CountsEachCasesGatesAndSaysWhyOneFailed) {
  Scene scene;
  scene.name = "drop";
  CaseResults results;
  results.scene = &scene;
  results.gates.push_back({Gate{"course/rk4", "position_max", 1e-6, 3}, 2e-9, true, ""});
  results.gates.push_back({Gate{"a<b>&\"c\"", "position_max", 1e-6, 4}, 0.5, false, ""});
  results.gates.push_back({Gate{"ode", "energy_max", 1e-3, 5}, std::nullopt, false, "diverged"});
  const std::string xml = junit_xml({results});
  EXPECT_NE(xml.find("<testsuites name=\"beachball gates\" tests=\"3\" failures=\"2\">"),
            std::string::npos)
      << xml;
  EXPECT_NE(xml.find("<testsuite name=\"drop\" tests=\"3\" failures=\"2\">"), std::string::npos)
      << xml;
  EXPECT_NE(xml.find("name=\"a&lt;b&gt;&amp;&quot;c&quot; position_max\""), std::string::npos)
      << xml;
  EXPECT_NE(xml.find("<failure message=\"position_max = 0.5 exceeds max 1e-06\"/>"),
            std::string::npos)
      << xml;
  EXPECT_NE(xml.find("<failure message=\"diverged\"/>"), std::string::npos) << xml;
  EXPECT_NE(xml.find("name=\"course/rk4 position_max\"/>"), std::string::npos) << xml;
}

}  // namespace
}  // namespace bb
