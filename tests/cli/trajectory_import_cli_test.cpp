// `--trajectory NAME@DT=FILE` on the command line (docs/output-files.md#trajectories, "In";
// docs/own-physics.md): the example program's files (docs/examples/import_trajectory/) as
// the row import/euler, its error computed again here from the closed form of the fall and
// its order about 1; bad files refused before any work with nothing written; a file that
// ends early is a row with its reason; a gate on an import passes or fails `check`;
// `stability` and several cases refuse the option.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "support/program.hpp"
#include "support/test_support.hpp"
#include "support/trajectory_csv.hpp"

namespace bb {
namespace {

namespace fs = std::filesystem;
using test::beachball;
using test::Outcome;

/// The example program on `case_file`, writing into `folder`: the options it prints.
std::string run_example(const std::string& case_file, const std::string& folder) {
  const Outcome o = test::shell(
      "python3 " + test::source_path("docs/examples/import_trajectory/explicit_euler.py") + " " +
      case_file + " " + folder);
  EXPECT_EQ(o.exit_code, 0) << o.out;
  return o.out.substr(0, o.out.find('\n'));
}

/// The row of `backend` at `dt` in a case's JSON.
nlohmann::json row_of(const nlohmann::json& results, const std::string& backend, double dt) {
  for (const auto& run : results["runs"])
    if (run["backend"] == backend && run["dt"].is_number() &&
        std::abs(run["dt"].get<double>() - dt) < 1e-12)
      return run;
  ADD_FAILURE() << "no row of " << backend << " at " << dt;
  return nlohmann::json::object();
}

/// A sphere falling from rest in still air: its height fallen after t seconds, with the
/// terminal speed vt = sqrt(m g / k), k = 1/2 rho Cd pi r^2: (vt^2 / g) ln cosh(g t / vt).
double fallen(double t, double mass, double radius, double cd, double rho, double g) {
  const double k = 0.5 * rho * cd * M_PI * radius * radius;
  const double vt = std::sqrt(mass * g / k);
  return vt * vt / g * std::log(std::cosh(g * t / vt));
}

TEST(TrajectoryImportCli, TheExampleProgramsRowHasItsOwnErrorAndOrderOne) {
  const std::string dir = test::fresh_dir("import_example");
  const std::string case_file = test::source_path("cases/drag_fall.toml");
  const std::string options = run_example(case_file, dir + "/euler");
  const Outcome o = beachball("run " + case_file + " --backends reference --no-cost " + options +
                              " --out " + dir + "/out");
  ASSERT_EQ(o.exit_code, 0) << o.out;
  const nlohmann::json results = nlohmann::json::parse(std::ifstream(dir + "/out/drag_fall.json"));
  // The case's numbers (cases/drag_fall.toml): both balls 20 kg/m^3, Cd 0.47, in air of 1.2.
  struct Ball {
    const char* name;
    double mass, radius, x, y;
  };
  const Ball balls[] = {{"elephant", 83.775804095727830, 1.0, -3.0, 150.0},
                        {"mouse", 0.083775804095727830, 0.1, 3.0, 150.0}};
  const double sample = 1.0 / 30.0;
  for (const auto& [file, dt] : {std::pair<const char*, double>{"euler@1-30.csv", 1.0 / 30.0},
                                 {"euler@1-60.csv", 1.0 / 60.0},
                                 {"euler@1-120.csv", 1.0 / 120.0}}) {
    // position_max by its definition (docs/observables.md): the largest distance of a body's
    // centre from where it should be, over every sample and every body.
    const test::TrajectoryCsv csv = test::read_trajectory(dir + "/euler/" + file);
    double worst = 0.0;
    for (const test::TrajectoryRow& row : csv.rows) {
      const double samples = row.t / sample;
      if (std::abs(samples - std::round(samples)) > 1e-6) continue;
      for (const Ball& b : balls)
        if (row.body == b.name) {
          const double y = b.y - fallen(row.t, b.mass, b.radius, 0.47, 1.2, 9.81);
          worst = std::max(worst, std::hypot(row.values[0] - b.x, row.values[1] - y));
        }
    }
    const nlohmann::json row = row_of(results, "import/euler", dt);
    ASSERT_EQ(row["status"], "ok") << row.dump();
    // The reference agrees with the closed form far below Euler's error.
    EXPECT_NEAR(row["errors"]["position_max"].get<double>(), worst, 1e-4 * worst) << file;
    EXPECT_GT(worst, 1e-3) << "explicit Euler has an error to measure";
    // The program's own time per step, from its cost_ns column.
    EXPECT_GT(row["cost"]["ns_per_step"].get<double>(), 0.0);
  }
  EXPECT_NEAR(results["order"]["import/euler"].get<double>(), 1.0, 0.1) << results["order"];
  // The other steps of the case have no row of it.
  for (const auto& run : results["runs"])
    if (run["backend"] == "import/euler") {
      EXPECT_GE(run["dt"].get<double>(), 1.0 / 120.0 - 1e-12);
    }
}

/// A folder with the minimal case (one ball falling in air, dt 0.1 s and 0.05 s, 1 s) and
/// the example program's files of it: {folder, the options}.
std::pair<std::string, std::string> minimal_with_example(const std::string& name,
                                                         const std::string& extra = "") {
  const std::string dir = test::fresh_dir(name);
  test::write_case(dir, "fall.toml", test::minimal_case("fall") + extra);
  return {dir, run_example(dir + "/fall.toml", dir + "/euler")};
}

TEST(TrajectoryImportCli, ABadFileIsRefusedBeforeAnyWorkWithNothingWritten) {
  const auto [dir, options] = minimal_with_example("import_refused");
  const std::string file = dir + "/euler/euler@1-20.csv";
  // A row of a body the case does not have, as line 4.
  std::string text = test::bytes(file);
  const std::size_t third = text.find('\n', text.find('\n', text.find('\n') + 1) + 1);
  text.insert(third + 1, "0.05,ghost,0,0,0,0,0,0,1,0,0,0,0,0,0,0\n");
  std::ofstream(file, std::ios::binary) << text;
  for (const std::string command : {"run", "report"}) {
    const Outcome o = beachball(command + " " + dir + "/fall.toml --no-cost " + options +
                                " --out " + dir + "/out");
    EXPECT_EQ(o.exit_code, 2) << command << ": " << o.out;
    EXPECT_NE(o.out.find(file + ":4: 'ghost' is not a body of case fall"), std::string::npos)
        << o.out;
    EXPECT_FALSE(fs::exists(dir + "/out")) << command;
  }
  const Outcome checked = beachball("check " + dir + "/fall.toml " + options);
  EXPECT_EQ(checked.exit_code, 2) << checked.out;
  EXPECT_NE(checked.out.find(file + ":4: 'ghost'"), std::string::npos) << checked.out;
  // A step the case does not have; a file that is not there.
  const Outcome step =
      beachball("run " + dir + "/fall.toml --trajectory e@1/30=" + file + " --out " + dir + "/out");
  EXPECT_EQ(step.exit_code, 2);
  EXPECT_NE(step.out.find("is not one of case fall's dt"), std::string::npos) << step.out;
  const Outcome none = beachball("run " + dir + "/fall.toml --trajectory e@1/20=" + dir +
                                 "/nothing.csv --out " + dir + "/out");
  EXPECT_EQ(none.exit_code, 2);
  EXPECT_NE(none.out.find(dir + "/nothing.csv: cannot be read"), std::string::npos) << none.out;
  EXPECT_FALSE(fs::exists(dir + "/out"));
}

TEST(TrajectoryImportCli, AFileThatEndsEarlyIsARowWithItsReason) {
  const auto [dir, options] = minimal_with_example("import_ends_early");
  // The program stopped at t = 0.5 s, in the middle of a line.
  const std::string file = dir + "/euler/euler@1-20.csv";
  const test::TrajectoryCsv whole = test::read_trajectory(file);
  std::string text = test::bytes(file);
  std::size_t cut = 0;
  for (int line = 0; line < 1 + 11; ++line) cut = text.find('\n', cut) + 1;
  std::ofstream(file, std::ios::binary | std::ios::trunc) << text.substr(0, cut + 10);
  const Outcome o = beachball("run " + dir + "/fall.toml --backends reference --no-cost " +
                              options + " --out " + dir + "/out");
  ASSERT_EQ(o.exit_code, 0) << o.out;
  const nlohmann::json results = nlohmann::json::parse(std::ifstream(dir + "/out/fall.json"));
  const nlohmann::json row = row_of(results, "import/euler", 0.05);
  EXPECT_EQ(row["status"], "error");
  EXPECT_NE(row["reason"].get<std::string>().find("the trajectory ends at t = 0.5 s of 1 s"),
            std::string::npos)
      << row.dump();
  EXPECT_TRUE(row["errors"].is_null());
  EXPECT_EQ(row_of(results, "import/euler", 0.1)["status"], "ok");
  EXPECT_GT(whole.rows.size(), 11u);
}

TEST(TrajectoryImportCli, AGateOnAnImportPassesOrFailsCheck) {
  // The gate's bound: twice, then half, the error the import has at report_dt.
  const auto [dir, options] = minimal_with_example("import_gate");
  const Outcome run = beachball("run " + dir + "/fall.toml --backends reference --no-cost " +
                                options + " --out " + dir + "/out");
  ASSERT_EQ(run.exit_code, 0) << run.out;
  const nlohmann::json results = nlohmann::json::parse(std::ifstream(dir + "/out/fall.json"));
  const double error = row_of(results, "import/euler", 0.05)["errors"]["position_max"];
  ASSERT_GT(error, 0.0);
  for (const auto& [factor, code] : {std::pair{2.0, 0}, {0.5, 1}}) {
    const std::string gated = dir + "/gated" + std::to_string(code);
    test::write_case(gated, "fall.toml",
                     test::minimal_case("fall") +
                         "[[gate]]\nbackend = \"import/euler\"\nmetric = \"position_max\"\nmax = " +
                         std::to_string(factor * error) + "\n");
    const Outcome o = beachball("check " + gated + "/fall.toml " + options);
    EXPECT_EQ(o.exit_code, code) << o.out;
    EXPECT_NE(o.out.find(code == 0 ? "ok   fall import/euler" : "FAIL fall import/euler"),
              std::string::npos)
        << o.out;
  }
}

TEST(TrajectoryImportCli, StabilityAndSeveralCasesRefuseTheOption) {
  const auto [dir, options] = minimal_with_example("import_refusals");
  const Outcome stability =
      beachball("stability " + dir + "/fall.toml " + options + " --out " + dir + "/out");
  EXPECT_EQ(stability.exit_code, 2);
  EXPECT_NE(stability.out.find("--trajectory: stability searches"), std::string::npos)
      << stability.out;
  test::write_case(dir, "other.toml", test::minimal_case("other"));
  const Outcome two = beachball("run " + dir + "/fall.toml " + dir + "/other.toml " + options +
                                " --out " + dir + "/out");
  EXPECT_EQ(two.exit_code, 2);
  EXPECT_NE(two.out.find("a trajectory is a run of one case"), std::string::npos) << two.out;
  EXPECT_FALSE(fs::exists(dir + "/out"));
}

}  // namespace
}  // namespace bb
