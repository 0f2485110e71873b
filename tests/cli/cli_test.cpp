// The `beachball` program end to end: outputs, exit codes, messages.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "run/engine_catalogue.hpp"
#include "support/engine_support.hpp"
#include "support/program.hpp"
#include "support/test_support.hpp"

namespace bb {
namespace {

namespace fs = std::filesystem;

using test::beachball;
using test::fresh_dir;
using test::Outcome;
using test::write_case;

TEST(Cli, RunWritesTheContractAndPrintsEveryBackend) {
  const std::string out = fresh_dir("run");
  const Outcome o = beachball("run " + test::source_path("cases/drag_fall.toml") + " --out " + out +
                              " --cost-time 0.001");
  ASSERT_EQ(o.exit_code, 0) << o.out;
  // Every backend has a row: the course's, the reference and each rigid engine described.
  std::vector<std::string> names = {"reference", "course/explicit-euler",
                                    "course/semi-implicit-euler", "course/velocity-verlet",
                                    "course/rk4"};
  for (const std::string& e : test::rigid_engines()) names.push_back(e);
  for (const std::string& name : names)
    EXPECT_NE(o.out.find(std::string("\n") + name + " "), std::string::npos) << name << "\n"
                                                                             << o.out;
  for (const char* ext : {".json", ".csv", ".md"})
    EXPECT_TRUE(fs::exists(out + "/drag_fall" + ext)) << ext;

  const auto j = nlohmann::json::parse(std::ifstream(out + "/drag_fall.json"));
  EXPECT_EQ(j["schema"], "beachball-results/1");
  EXPECT_EQ(j["case"], "drag_fall");
  // The version of every library a run used: each described rigid engine's own.
  std::vector<std::string> libs = {"beachball", "gsl"};
  for (const std::string& e : test::rigid_engines())
    if (test::engine(e) != nullptr) libs.push_back(test::engine(e)->library_version().first);
  for (const std::string& lib : libs) EXPECT_TRUE(j["versions"].contains(lib)) << lib;
  for (const char* key : {"method", "tolerance", "self_check", "self_check_method"})
    EXPECT_TRUE(j["reference"].contains(key)) << key;
  // The self-check compares every state component, each a number where it was measured.
  for (const char* key :
       {"self_check", "self_check_velocity", "self_check_orientation", "self_check_spin"})
    EXPECT_TRUE(j["reference"][key].is_number()) << key;
  EXPECT_TRUE(j["order"].is_object());
  EXPECT_TRUE(j["stability"].is_object());
  ASSERT_GE(j["runs"].size(), 1u + 8u * 6u);
  EXPECT_EQ(j["runs"][0]["backend"], "reference");
  EXPECT_TRUE(j["runs"][0]["dt"].is_null());
  for (const auto& run : j["runs"]) {
    for (const char* key : {"backend", "dt", "status", "reason", "diverged_at", "steps", "cost",
                            "errors", "observables", "engine_settings"})
      EXPECT_TRUE(run.contains(key)) << key;
    if (run["status"] != "ok") continue;
    for (const char* key : {"ns_per_step", "seconds_per_simulated_second", "repeats"})
      EXPECT_TRUE(run["cost"].contains(key)) << key;
    if (run["backend"] == "reference") continue;
    for (const char* key :
         {"position_max", "position_rms", "position_final", "velocity_max", "energy_max"})
      EXPECT_TRUE(run["errors"][key].is_number()) << key;
    EXPECT_TRUE(run["observables"]["final_speed/elephant"]["value"].is_number());
    EXPECT_TRUE(run["observables"]["terminal_velocity/elephant"]["value"].is_number());
    // The terminal speed sqrt(2 m g / (rho Cd A)) of the elephant, from the case file.
    EXPECT_NEAR(run["observables"]["terminal_velocity/elephant"]["reference"].get<double>(),
                30.4575, 1e-4);
  }
  EXPECT_NEAR(j["order"]["course/rk4"].get<double>(), 4.0, 0.2);

  // The CSV has a header and one row per run.
  std::ifstream csv(out + "/drag_fall.csv");
  std::string header;
  std::getline(csv, header);
  EXPECT_EQ(header.rfind("case,backend,dt,status,", 0), 0u);
  int rows = 0;
  for (std::string line; std::getline(csv, line);) ++rows;
  EXPECT_EQ(rows, static_cast<int>(j["runs"].size()));
}

TEST(Cli, ACaseWrittenFromTheFormatAloneRunsOnEveryBackend) {
  const std::string out = fresh_dir("external");
  const Outcome o = beachball("run " + test::source_path("tests/cases/thrown_into_wind.toml") +
                              " --out " + out + " --no-cost");
  ASSERT_EQ(o.exit_code, 0) << o.out;
  const auto j = nlohmann::json::parse(std::ifstream(out + "/thrown_into_wind.json"));
  std::vector<std::string> not_built;
  for (const auto& run : j["runs"])
    if (test::described_but_not_built(run["backend"]))
      not_built.push_back(run["backend"]);
    else
      EXPECT_EQ(run["status"], "ok") << run["backend"] << ": " << run["reason"];
  BB_SKIP_IF_MISSING(test::not_built(not_built));
}

TEST(Cli, BadInputExitsTwoNamingFileAndLineAndWritesNothing) {
  const std::string dir = fresh_dir("bad");
  const std::string good = write_case(dir, "good.toml", test::kMinimalCase);
  std::string text = test::kMinimalCase;
  const std::size_t at = text.find("mass = 1.0");
  text.replace(at, 10, "mass = -2.0");
  const auto line = 1 + std::count(text.begin(), text.begin() + at, '\n');
  const std::string bad = write_case(dir, "bad.toml", text);
  const std::string out = dir + "/out";
  // The good case comes first: still nothing may be written.
  const Outcome o = beachball("run " + good + " " + bad + " --out " + out);
  EXPECT_EQ(o.exit_code, 2);
  EXPECT_NE(o.out.find(bad + ":" + std::to_string(line) +
                       ": 'mass' in [[body]] 'ball' must be between 1e-09 and 1e+09, not -2"),
            std::string::npos)
      << o.out;
  EXPECT_FALSE(fs::exists(out));
}

TEST(Cli, UsageErrorsExitTwo) {
  EXPECT_EQ(beachball("run").exit_code, 2);
  EXPECT_EQ(beachball("frobnicate").exit_code, 2);
  EXPECT_EQ(beachball("run " + test::source_path("cases/drag_fall.toml") +
                      " --backends physx --no-cost --out " + fresh_dir("usage"))
                .exit_code,
            2);
  EXPECT_EQ(beachball("run " + test::source_path("cases/drag_fall.toml") + " --dt abc --out " +
                      fresh_dir("usage"))
                .exit_code,
            2);
}

// The refusal of an unknown backend lists the backends the case runs: those that exist in
// this build and can run it (drag_fall is 2D without springs: no springs by hand).
TEST(Cli, AnUnknownBackendIsRefusedWithTheBackendsThatRunTheCase) {
  const test::Outcome o = beachball("run " + test::source_path("cases/drag_fall.toml") +
                                    " --backends physx --no-cost --out " + fresh_dir("usage"));
  EXPECT_EQ(o.exit_code, 2);
  EXPECT_NE(o.out.find("it runs: reference, course/"), std::string::npos) << o.out;
  EXPECT_EQ(o.out.find("ode/force"), std::string::npos) << o.out;
}

TEST(Cli, CheckFailsOnATightGateAndPassesOnALooseOne) {
  const std::string dir = fresh_dir("check");
  const auto gated = [&](double max) {
    return std::string(test::kMinimalCase) +
           "\n[[gate]]\nbackend = \"course/semi-implicit-euler\"\nmetric = \"position_max\"\nmax "
           "= " +
           std::to_string(max) + "\n";
  };
  const std::string tight = write_case(dir, "tight.toml", gated(1e-9));
  const std::string loose = write_case(dir, "loose.toml", gated(1.0));
  const std::string junit = dir + "/gates.xml";
  const Outcome failed = beachball("check " + tight + " --junit " + junit);
  EXPECT_EQ(failed.exit_code, 1) << failed.out;
  EXPECT_NE(failed.out.find("FAIL"), std::string::npos);
  std::ifstream xml(junit);
  const std::string text((std::istreambuf_iterator<char>(xml)), std::istreambuf_iterator<char>());
  EXPECT_NE(text.find("<failure message=\"position_max"), std::string::npos) << text;
  EXPECT_NE(text.find("course/semi-implicit-euler position_max"), std::string::npos) << text;
  const Outcome passed = beachball("check " + loose);
  EXPECT_EQ(passed.exit_code, 0) << passed.out;
}

TEST(Cli, ListSaysWhatWasBuiltAndWhoRunsWhat) {
  const Outcome o = beachball("list");
  ASSERT_EQ(o.exit_code, 0) << o.out;
  for (const char* name : {"bullet ", "bullet-float ", "box2d ", "ode "})
    EXPECT_NE(o.out.find(std::string(name)), std::string::npos) << name;
  EXPECT_NE(o.out.find("built (bullet 3."), std::string::npos) << o.out;
  EXPECT_NE(o.out.find("unsupported: 3d"), std::string::npos) << o.out;
}

TEST(Cli, HelpNamesEveryEngineTheCatalogueDescribes) {
  const test::Outcome o = test::beachball("--help");
  ASSERT_EQ(o.exit_code, 0) << o.out;
  std::string lower = o.out;
  std::transform(lower.begin(), lower.end(), lower.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  for (const EngineDescription& engine : engine_catalogue())
    EXPECT_NE(lower.find(engine.engine), std::string::npos) << engine.engine << "\n" << o.out;
}

}  // namespace
}  // namespace bb
