// A trajectory file from another program is checked against its case before any work
// (docs/output-files.md#trajectories, "In"): each bad file is refused with its file, the
// line and the problem; a file that ends early, one with rows at the samples only and one
// with the program's cost are read for what they hold.
#include "run/trajectory_reader.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "study/case_error.hpp"
#include "support/program.hpp"
#include "support/test_support.hpp"

namespace bb {
namespace {

/// Two points in 2D, no gravity, 0.4 s sampled every 0.1 s, steps of 0.05 s (2 per sample).
constexpr const char* kPair = R"(name = "pair"
dims = 2
duration = 0.4
sample = 0.1
dt = [0.05]
report_dt = 0.05
gravity = [0.0, 0.0, 0.0]
[[body]]
name = "a"
shape = "point"
mass = 1.0
position = [0.0, 0.0, 0.0]
[[body]]
name = "b"
shape = "point"
mass = 1.0
position = [1.0, 0.0, 0.0]
velocity = [1.0, 0.0, 0.0]
)";

constexpr const char* kHeader = "t,body,x,y,z,vx,vy,vz\n";

/// Rows of both bodies at step k (b moving at 1 m/s along x).
std::string rows_at(int k, double dt = 0.05) {
  const std::string t = std::to_string(k * dt);
  return t + ",a,0,0,0,0,0,0\n" + t + ",b," + std::to_string(1.0 + k * dt) + ",0,0,1,0,0\n";
}

/// Rows at every step from 0 to `last`.
std::string every_step(int last) {
  std::string out = kHeader;
  for (int k = 0; k <= last; ++k) out += rows_at(k);
  return out;
}

/// Writes `text` to a fresh file named `name`; returns its path.
std::string file_with(const std::string& name, const std::string& text) {
  const std::string dir = test::fresh_dir("trajectory_reader_" + name);
  std::filesystem::create_directories(dir);
  std::ofstream(dir + "/" + name + ".csv", std::ios::binary) << text;
  return dir + "/" + name + ".csv";
}

/// The refusal of `text`: its line and problem; fails the test when it is read.
CaseError refusal(const std::string& name, const std::string& text) {
  const Scene scene = test::scene_from(kPair);
  const std::string path = file_with(name, text);
  try {
    read_trajectory(scene, 0.05, path);
  } catch (const CaseError& e) {
    EXPECT_EQ(e.file(), path);
    return e;
  }
  ADD_FAILURE() << name << " was read";
  return CaseError("", 0, "");
}

/// Expects `text` refused at `line` with `words` in the problem.
void expect_refused(const std::string& name, const std::string& text, int line,
                    const std::string& words) {
  const CaseError e = refusal(name, text);
  EXPECT_EQ(e.line(), line) << name << ": " << e.what();
  EXPECT_NE(e.problem().find(words), std::string::npos) << name << ": " << e.what();
}

TEST(TrajectoryReader, AWholeFileIsEveryStepsState) {
  const Scene scene = test::scene_from(kPair);
  const ImportedTrajectory t = read_trajectory(scene, 0.05, file_with("whole", every_step(8)));
  EXPECT_EQ(t.stride, 1);
  EXPECT_EQ(t.run_steps, 8);
  ASSERT_EQ(t.states.size(), 9u);
  EXPECT_DOUBLE_EQ(t.states[8][1].position.x(), 1.4);
  EXPECT_TRUE(t.cost_ns.empty());
}

TEST(TrajectoryReader, BadFilesAreRefusedWithTheirLine) {
  expect_refused("header", "t,body,x,y,z\n" + rows_at(0), 1, "the header is");
  expect_refused("unknown_body", every_step(2) + "0.15,c,0,0,0,0,0,0\n", 8, "'c' is not a body");
  // Line 6 starts t = 0.1, which lacks b; the row at t = 0.15 finds it missing.
  std::string missing = every_step(1) + "0.1,a,0,0,0,0,0,0\n" + rows_at(3);
  expect_refused("missing_body", missing, 6, "body 'b' has no row at t = 0.1");
  std::string twice = every_step(1) + "0.05,a,0,0,0,0,0,0\n";
  expect_refused("twice", twice, 6, "body 'a' twice");
  expect_refused("not_a_number", kHeader + std::string("0,a,0,zero,0,0,0,0\n"), 2,
                 "'zero' is not a number");
  std::string out_of_order = kHeader + rows_at(0) + rows_at(2) + rows_at(1);
  expect_refused("order", out_of_order, 6, "out of order");
  std::string off_grid = kHeader + rows_at(0) + "0.051,a,0,0,0,0,0,0\n";
  expect_refused("off_grid", off_grid, 4, "not on the grid of steps");
  std::string gap = kHeader + rows_at(0) + rows_at(1) + rows_at(3);
  expect_refused("gap", gap, 6, "the time 0.1 s is missing");
  expect_refused("late_start", kHeader + rows_at(1), 2, "not 0");
  expect_refused("past_end", every_step(8) + rows_at(9), 20, "past the end");
  std::string columns = kHeader + std::string("0,a,0,0,0,0,0\n");
  expect_refused("columns", columns, 2, "has 7 columns");
  expect_refused("empty", std::string(kHeader), 2, "no rows");
  std::string cost = "t,body,x,y,z,vx,vy,vz,cost_ns\n0,a,0,0,0,0,0,0,-5\n";
  expect_refused("cost", cost, 2, "cost_ns '-5'");
}

TEST(TrajectoryReader, AMissingFileIsRefused) {
  const Scene scene = test::scene_from(kPair);
  EXPECT_THROW(read_trajectory(scene, 0.05, "/nonexistent/run.csv"), CaseError);
}

TEST(TrajectoryReader, NotFiniteValuesOnlyInTheLastRowsUpToTheSample) {
  const Scene scene = test::scene_from(kPair);
  // nan at step 3, the file ending at the sample after it (step 4): a run that diverged.
  std::string diverged = every_step(2) + "0.15,a,nan,0,0,0,0,0\n0.15,b,inf,0,0,0,0,0\n" +
                         "0.2,a,nan,0,0,0,0,0\n0.2,b,nan,0,0,0,0,0\n";
  const ImportedTrajectory t = read_trajectory(scene, 0.05, file_with("diverged", diverged));
  EXPECT_EQ(t.last_step(), 4);
  EXPECT_TRUE(std::isnan(t.states[4][0].position.x()));
  // Rows past that sample: the nan was not the run's end.
  expect_refused("nan_then_more", diverged + rows_at(5), 8, "not finite");
  expect_refused("nan_at_start",
                 kHeader + std::string("0,a,nan,0,0,0,0,0\n0,b,0,0,0,0,0,0\n") + rows_at(1), 2,
                 "not finite");
}

TEST(TrajectoryReader, AFileThatEndsEarlyIsReadToItsLastWholeTime) {
  const Scene scene = test::scene_from(kPair);
  // Cut in the middle of a line (no newline) and in the middle of a time.
  std::string cut = every_step(4) + "0.25,a,0,0,0,0,0,0\n0.25,b,1.2";
  const ImportedTrajectory t = read_trajectory(scene, 0.05, file_with("cut", cut));
  EXPECT_EQ(t.last_step(), 4);
  EXPECT_EQ(t.states.size(), 5u);
}

TEST(TrajectoryReader, RowsAtTheSamplesOnlyStepAsManyStepsAsASample) {
  const Scene scene = test::scene_from(kPair);
  std::string samples = kHeader;
  for (int k = 0; k <= 8; k += 2) samples += rows_at(k);
  const ImportedTrajectory t = read_trajectory(scene, 0.05, file_with("samples", samples));
  EXPECT_EQ(t.stride, 2);
  EXPECT_TRUE(t.samples_only());
  EXPECT_EQ(t.last_step(), 8);
  // Rows every third step are neither.
  std::string thirds = kHeader + rows_at(0) + rows_at(3);
  expect_refused("thirds", thirds, 4, "rows are at every step, or at every sample");
}

TEST(TrajectoryReader, TheProgramsCostIsItsTimePerStepAfterTheStart) {
  const Scene scene = test::scene_from(kPair);
  std::string text = "t,body,x,y,z,vx,vy,vz,cost_ns\n";
  for (int k = 0; k <= 8; ++k) {
    const std::string t = std::to_string(k * 0.05);
    const std::string ns = std::to_string(100 * k);
    text += t + ",a,0,0,0,0,0,0," + ns + "\n" + t + ",b,1,0,0,1,0,0," + ns + "\n";
  }
  const ImportedTrajectory t = read_trajectory(scene, 0.05, file_with("cost", text));
  ASSERT_EQ(t.cost_ns.size(), 8u);
  EXPECT_DOUBLE_EQ(t.cost_ns.front(), 100.0);
  EXPECT_DOUBLE_EQ(t.cost_ns.back(), 800.0);
}

TEST(TrajectoryReader, ATimeSummedStepByStepIsOnTheGrid) {
  const Scene scene = test::scene_from(kPair);
  std::string text = kHeader;
  double t = 0.0;
  for (int k = 0; k <= 8; ++k, t += 0.05) {
    char stamp[64];
    std::snprintf(stamp, sizeof stamp, "%.17g", t);
    text += std::string(stamp) + ",a,0,0,0,0,0,0\n" + stamp + ",b,1,0,0,1,0,0\n";
  }
  EXPECT_EQ(read_trajectory(scene, 0.05, file_with("summed", text)).states.size(), 9u);
}

}  // namespace
}  // namespace bb
