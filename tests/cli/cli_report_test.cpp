// The `beachball` program end to end, its reports: the index, the pages, the plots, the
// claims ledger, sweeps and stability (cli_test.cpp has the other commands; the two halves
// compile in parallel).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "support/program.hpp"
#include "support/test_support.hpp"

namespace bb {
namespace {

namespace fs = std::filesystem;

using test::beachball;
using test::fresh_dir;
using test::Outcome;

TEST(Cli, TheIndexHasOneTablePerCourseSectionWithItsOwnBackends) {
  const std::string out = fresh_dir("report_sections");
  // Given drag first, the springs still come first: the course text's order.
  const Outcome o =
      beachball("report " + test::source_path("cases/drag_fall.toml") + " " +
                test::source_path("cases/spring_pair.toml") + " --out " + out + " --no-cost");
  ASSERT_EQ(o.exit_code, 0) << o.out;
  std::ifstream index(out + "/README.md");
  const std::string text((std::istreambuf_iterator<char>(index)), std::istreambuf_iterator<char>());
  const std::size_t springs = text.find("\n### 7. Springs\n"),
                    wind = text.find("\n### 8. Wind effects\n");
  ASSERT_NE(springs, std::string::npos) << text;
  ASSERT_NE(wind, std::string::npos) << text;
  EXPECT_LT(springs, wind);
  // The soft body runs only where there are springs: a column there, none under drag.
  const std::string spring_table = text.substr(springs, wind - springs);
  const std::string wind_table = text.substr(wind, text.find("\n## ", wind) - wind);
  EXPECT_NE(spring_table.find("bullet-softbody"), std::string::npos) << spring_table;
  EXPECT_EQ(wind_table.find("bullet-softbody"), std::string::npos) << wind_table;
  EXPECT_NE(wind_table.find("(drag_fall.md)"), std::string::npos);
  EXPECT_EQ(spring_table.find("(drag_fall.md)"), std::string::npos);
}

TEST(Cli, ReportWritesAnIndexPagesPlotsAndStability) {
  const std::string out = fresh_dir("report");
  const Outcome o =
      beachball("report " + test::source_path("cases/three_beachballs_2.toml") + " " +
                test::source_path("cases/beachball_shells.toml") + " --out " + out + " --no-cost");
  ASSERT_EQ(o.exit_code, 0) << o.out;
  std::ifstream index(out + "/README.md");
  const std::string text((std::istreambuf_iterator<char>(index)), std::istreambuf_iterator<char>());
  for (const char* name : {"three_beachballs_2", "beachball_shells"}) {
    EXPECT_NE(text.find(std::string("(") + name + ".md)"), std::string::npos) << name;
    std::ifstream page(out + "/" + name + ".md");
    const std::string md((std::istreambuf_iterator<char>(page)), std::istreambuf_iterator<char>());
    // Every image the page shows exists beside it.
    int images = 0;
    for (std::size_t at = md.find("]("); at != std::string::npos; at = md.find("](", at + 1)) {
      const std::string file = md.substr(at + 2, md.find(')', at) - at - 2);
      if (!file.ends_with(".svg")) continue;
      ++images;
      EXPECT_TRUE(fs::exists(out + "/" + file)) << file;
    }
    // The motion view and its still, work precision, trajectory, energy, error over time;
    // and the speed where air drags a body.
    std::ifstream source(test::source_path("cases/" + std::string(name) + ".toml"));
    const std::string toml((std::istreambuf_iterator<char>(source)), {});
    const bool air = toml.find("drag_coefficient") != std::string::npos;
    EXPECT_EQ(images, air ? 7 : 6) << name;
    for (const char* section :
         {"## Stability", "## Work precision", "## Gates", "## Engine settings"})
      EXPECT_NE(md.find(section), std::string::npos) << name << " lacks " << section;
    // The engines' settings are folded away, not 18 KB of the page.
    EXPECT_NE(md.find("<details>", md.find("## Engine settings")), std::string::npos) << name;
    const auto j = nlohmann::json::parse(std::ifstream(out + "/" + name + ".json"));
    EXPECT_TRUE(j["stability"].contains("course/rk4")) << name;
    EXPECT_TRUE(j["stability"]["course/rk4"]["theory"].is_number()) << name;
  }
  EXPECT_NE(text.find("unsupported"), std::string::npos);  // box2d on the 3D case
  // Neither case turns a body: the index has no rotation section.
  EXPECT_EQ(text.find("## Rotation"), std::string::npos);
}

// The claims ledger: written beside the index, linked before any case, one row per claim
// with its verdicts computed from the runs.
TEST(Cli, TheClaimsLedgerIsLinkedFirstAndJudgesEveryBackend) {
  const std::string out = fresh_dir("report_claims");
  ASSERT_EQ(beachball("report " + test::source_path("cases/drag_fall.toml") + " --out " + out +
                      " --no-cost")
                .exit_code,
            0);
  std::ifstream index(out + "/README.md");
  const std::string text((std::istreambuf_iterator<char>(index)), std::istreambuf_iterator<char>());
  ASSERT_NE(text.find("(claims.md)"), std::string::npos);
  EXPECT_LT(text.find("(claims.md)"), text.find("(drag_fall.md)"));
  std::ifstream ledger(out + "/claims.md");
  const std::string md((std::istreambuf_iterator<char>(ledger)), std::istreambuf_iterator<char>());
  EXPECT_NE(md.find("The elephant falls faster than the mouse"), std::string::npos);
  // Each claim beside the course text's words it tests, with their section.
  EXPECT_NE(md.find("8. Wind effects: \"And, for these bowling balls, the elephant does indeed "
                    "fall faster.\""),
            std::string::npos)
      << md;
  EXPECT_NE(md.find("reference: **holds**"), std::string::npos) << md;
  EXPECT_NE(md.find("ode: **holds**"), std::string::npos) << md;
  const auto j = nlohmann::json::parse(std::ifstream(out + "/drag_fall.json"));
  EXPECT_EQ(j["claims"][0]["verdicts"]["reference"]["verdict"], "holds");
  EXPECT_EQ(j["claims"][0]["quote"],
            "And, for these bowling balls, the elephant does indeed fall faster.");
  EXPECT_EQ(j["claims"][0]["own"], false);
  // The case's page shows its own claims.
  std::ifstream page(out + "/drag_fall.md");
  const std::string case_md((std::istreambuf_iterator<char>(page)),
                            std::istreambuf_iterator<char>());
  EXPECT_NE(case_md.find("## Claims"), std::string::npos);
  EXPECT_NE(case_md.find("The larger ball reaches its final speed later"), std::string::npos);
}

// A case with a [[sweep]]: the index lists it, its page has the sweep section with what the
// published study found, and its JSON carries every point.
TEST(Cli, ASweepCaseIsListedInTheIndexAndItsPageShowsTheSweep) {
  const std::string out = fresh_dir("report_sweep");
  ASSERT_EQ(beachball("report " + test::source_path("cases/pal_restitution.toml") + " --out " +
                      out + " --no-cost")
                .exit_code,
            0);
  std::ifstream index(out + "/README.md");
  const std::string text((std::istreambuf_iterator<char>(index)), std::istreambuf_iterator<char>());
  EXPECT_NE(text.find("[pal_restitution](pal_restitution.md): `ground.restitution` over 3 values"),
            std::string::npos)
      << text;
  std::ifstream page(out + "/pal_restitution.md");
  const std::string md((std::istreambuf_iterator<char>(page)), std::istreambuf_iterator<char>());
  EXPECT_NE(md.find("## Sweep of `ground.restitution`"), std::string::npos);
  EXPECT_NE(md.find("What the published study found"), std::string::npos);
  EXPECT_NE(md.find("ground.restitution = 0.9"), std::string::npos);
  const auto j = nlohmann::json::parse(std::ifstream(out + "/pal_restitution.json"));
  ASSERT_EQ(j["sweep"]["points"].size(), 3u);
  // The reference's first apex at e = 0.9: r + e^2 h = 0.5 + 0.81 m.
  EXPECT_NEAR(j["sweep"]["points"][2]["runs"][0]["observables"]["bounce_apex/ball/1"]["value"]
                  .get<double>(),
              1.31, 1e-9);
}

// A case whose bodies turn has its rotation plot on its page, and the index shows it too.
TEST(Cli, TheIndexGathersTheRotationPlots) {
  const std::string out = fresh_dir("report_rotation");
  ASSERT_EQ(beachball("report " + test::source_path("cases/plank_free.toml") + " " +
                      test::source_path("cases/arrow.toml") + " --out " + out + " --no-cost")
                .exit_code,
            0);
  std::ifstream index(out + "/README.md");
  const std::string text((std::istreambuf_iterator<char>(index)), std::istreambuf_iterator<char>());
  const std::size_t section = text.find("## Rotation");
  ASSERT_NE(section, std::string::npos);
  EXPECT_NE(text.find("(plank_free-rotation.svg)", section), std::string::npos);
  EXPECT_EQ(text.find("arrow-rotation", section), std::string::npos);
  EXPECT_TRUE(fs::exists(out + "/plank_free-rotation.svg"));
}

// A report folder reused for a smaller suite keeps no page, data or plot of a case that is
// no longer in it: the new report replaces the old folder as a whole.
TEST(Cli, AReusedReportFolderLosesThePagesOfCasesNoLongerReported) {
  const std::string out = fresh_dir("report_reused");
  const std::string push = test::source_path("cases/push.toml");
  const std::string arrow = test::source_path("cases/arrow.toml");
  ASSERT_EQ(beachball("report " + push + " " + arrow + " --out " + out + " --no-cost").exit_code,
            0);
  ASSERT_TRUE(fs::exists(out + "/arrow.md"));
  ASSERT_EQ(beachball("report " + push + " --out " + out + " --no-cost").exit_code, 0);
  EXPECT_TRUE(fs::exists(out + "/push.md"));
  for (const auto& entry : fs::directory_iterator(out))
    EXPECT_EQ(entry.path().filename().string().find("arrow"), std::string::npos) << entry.path();
}

TEST(Cli, StabilityWritesTheStabilitySection) {
  const std::string out = fresh_dir("stability");
  const Outcome o = beachball("stability " + test::source_path("cases/drag_fall.toml") +
                              " --backends course/rk4,ode --out " + out);
  ASSERT_EQ(o.exit_code, 0) << o.out;
  // Named apart from a run's drag_fall.json, .csv and .md, so both can share a folder.
  const auto j = nlohmann::json::parse(std::ifstream(out + "/drag_fall-stability.json"));
  EXPECT_TRUE(fs::exists(out + "/drag_fall-stability.md"));
  EXPECT_FALSE(fs::exists(out + "/drag_fall.json"));
  EXPECT_EQ(j["schema"], "beachball-results/1");
  EXPECT_EQ(j["stability"].size(), 2u);
  for (const char* b : {"course/rk4", "ode"}) {
    EXPECT_TRUE(j["stability"][b]["status"].is_string()) << b;
    EXPECT_GE(j["stability"][b]["trials"].get<int>(), 1) << b;
  }
  EXPECT_EQ(beachball("stability " + test::source_path("cases/drag_fall.toml") +
                      " --backends reference --out " + out)
                .exit_code,
            2);
}

}  // namespace
}  // namespace bb
