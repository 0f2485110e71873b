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
  results.gates.push_back({Gate{"course/rk4", "position_max", 1e-6, 3}, 2e-9, true, "", ""});
  results.gates.push_back({Gate{"a<b>&\"c\"", "position_max", 1e-6, 4}, 0.5, false, "", ""});
  results.gates.push_back(
      {Gate{"ode", "energy_max", 1e-3, 5}, std::nullopt, false, "diverged", ""});
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

TEST(JunitWriter, ATestCasePerBackendAndMetricComparedFailedWhereADtGotWorse) {
  Scene scene;
  scene.name = "drop";
  CaseResults results;
  results.scene = &scene;
  const auto compared = [](double dt, Change change, double before, double now) {
    return BaselineComparison{"course/rk4", dt, "position_max", change, before, now, ""};
  };
  results.baseline = {compared(1.0 / 60, Change::Worse, 0.0015, 0.003),
                      compared(1.0 / 120, Change::Unchanged, 1e-4, 1e-4),
                      {"ode", 0.01, "energy_max", Change::Unchanged, 0.2, 0.2, ""},
                      {"bullet", 0.01, "", Change::NotCompared, {}, {}, "not in the baseline"},
                      {"box2d", 0.01, "x/ball", Change::NothingToCompare, {}, {}, "none"}};
  const std::string xml = junit_xml({results});
  // Three test cases: the worse one, the unchanged one and the one named; none for nothing.
  EXPECT_NE(xml.find("<testsuite name=\"drop\" tests=\"3\" failures=\"1\" skipped=\"1\">"),
            std::string::npos)
      << xml;
  EXPECT_NE(xml.find("name=\"baseline course/rk4 position_max\">\n      <failure message=\"worse: "
                     "course/rk4 dt 1/60 position_max: 0.0015 -&gt; 0.003 (x2)\"/>"),
            std::string::npos)
      << xml;
  EXPECT_NE(xml.find("name=\"baseline ode energy_max\"/>"), std::string::npos) << xml;
  EXPECT_NE(xml.find("<skipped message=\"not compared: bullet dt 1/100: not in the baseline\"/>"),
            std::string::npos)
      << xml;
}

}  // namespace
}  // namespace bb
