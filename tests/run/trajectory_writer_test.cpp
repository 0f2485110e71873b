// A run's trajectory file (docs/output-files.md#trajectories) holds the run itself: a row
// per body at every step, t = k dt exactly, the numbers of the run's own states bit for
// bit; the reference's rows are its samples; rotation columns where a body can turn; a run
// that stopped early ends where it stopped; a file that cannot be written says why.
#include "run/trajectory_writer.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>

#include "course/course_backend.hpp"
#include "run/accuracy_run.hpp"
#include "run/registry.hpp"
#include "study/start_case.hpp"
#include "support/program.hpp"
#include "support/test_support.hpp"
#include "support/trajectory_csv.hpp"

namespace bb {
namespace {

/// Two points on a spring of `stiffness` N/m in 2D, without gravity, for 1 s sampled every
/// 0.1 s, at steps of 0.05 s and 0.025 s.
std::string spring_points(double stiffness) {
  return R"(name = "pair"
dims = 2
duration = 1.0
sample = 0.1
dt = [0.05, 0.025]
report_dt = 0.05
gravity = [0.0, 0.0, 0.0]
[[body]]
name = "left"
shape = "point"
mass = 1.0
position = [-0.55, 0.0, 0.0]
[[body]]
name = "right"
shape = "point"
mass = 1.0
position = [0.55, 0.1, 0.0]
velocity = [0.0, 0.5, 0.0]
[[spring]]
bodies = ["left", "right"]
stiffness = )" +
         std::to_string(stiffness) + "\ndamping = 0.0\nrest_length = 1.0\n";
}

const CourseBackend kExplicitEuler({"course/explicit-euler", "explicit-euler", "mirror", "clamp"});

/// A file path under the test's temporary folder, fresh.
std::string trajectory_path(const std::string& name) {
  const std::string dir = test::fresh_dir("trajectory_writer_" + name);
  std::filesystem::create_directories(dir);
  return dir + "/" + name + ".csv";
}

/// `run` of `backend` on `scene` at `dt` with its steps written to `path`; the writer's
/// problem must be none.
RunRecord run_writing(const Backend& backend, const Scene& scene, double dt,
                      const std::string& path) {
  TrajectoryWriter writer(path, scene);
  RunRecord run = run_accuracy(backend, scene, dt, false, &writer);
  EXPECT_EQ(writer.close(), "");
  return run;
}

/// Whether `row` holds `body`'s state: position and velocity, and orientation and spin when
/// the row has them, each the same double.
void expect_state(const test::TrajectoryRow& row, const BodyState& body, const std::string& at) {
  ASSERT_GE(row.values.size(), 6u) << at;
  for (int k = 0; k < 3; ++k) {
    EXPECT_EQ(row.values[k], body.position[k]) << at;
    EXPECT_EQ(row.values[3 + k], body.velocity[k]) << at;
  }
  if (row.values.size() < 13) return;
  EXPECT_EQ(row.values[6], body.orientation.w()) << at;
  EXPECT_EQ(row.values[7], body.orientation.x()) << at;
  EXPECT_EQ(row.values[8], body.orientation.y()) << at;
  EXPECT_EQ(row.values[9], body.orientation.z()) << at;
  for (int k = 0; k < 3; ++k) EXPECT_EQ(row.values[10 + k], body.angular_velocity[k]) << at;
}

TEST(TrajectoryFile, EveryStepIsARowAtKTimesDtHoldingTheBackendsOwnState) {
  const Scene scene = test::scene_from(spring_points(10.0));
  const double dt = 0.025;
  const std::string path = trajectory_path("every_step");
  const RunRecord run = run_writing(kExplicitEuler, scene, dt, path);
  ASSERT_EQ(run.status, RunStatus::Ok) << run.reason;
  const test::TrajectoryCsv file = test::read_trajectory(path);
  EXPECT_EQ(file.header, "t,body,x,y,z,vx,vy,vz");  // points: no rotation columns
  EXPECT_TRUE(file.complete);
  const std::size_t bodies = scene.bodies.size();
  const long steps = static_cast<long>(scene.steps_per_sample(dt)) * scene.sample_count();
  ASSERT_EQ(file.rows.size(), bodies * static_cast<std::size_t>(steps + 1));
  // The backend stepped here, state by state, beside the file's rows.
  const auto sim = start_case(kExplicitEuler, scene, dt);
  State state(bodies);
  for (long k = 0; k <= steps; ++k) {
    if (k > 0) sim->step();
    sim->read(state);
    for (std::size_t b = 0; b < bodies; ++b) {
      const test::TrajectoryRow& row = file.rows[static_cast<std::size_t>(k) * bodies + b];
      const std::string at = "step " + std::to_string(k) + ", " + scene.bodies[b].name;
      EXPECT_EQ(row.t, static_cast<double>(k) * dt) << at;
      EXPECT_EQ(row.body, scene.bodies[b].name) << at;
      expect_state(row, state[b], at);
      EXPECT_EQ(row.values[2], 0.0) << at << ": z in 2D";
      EXPECT_EQ(row.values[5], 0.0) << at << ": vz in 2D";
    }
  }
  // At the sample times the rows are the very states the run's errors are measured from,
  // and writing them changed nothing of the run.
  const RunRecord plain = run_accuracy(kExplicitEuler, scene, dt);
  const std::size_t per_sample = static_cast<std::size_t>(scene.steps_per_sample(dt));
  ASSERT_EQ(run.trajectory.states.size(), plain.trajectory.states.size());
  for (std::size_t j = 0; j < run.trajectory.states.size(); ++j)
    for (std::size_t b = 0; b < bodies; ++b) {
      const std::string at = "sample " + std::to_string(j) + ", " + scene.bodies[b].name;
      expect_state(file.rows[j * per_sample * bodies + b], run.trajectory.states[j][b], at);
      EXPECT_EQ(run.trajectory.states[j][b].position, plain.trajectory.states[j][b].position) << at;
    }
}

TEST(TrajectoryFile, TheReferencesRowsAreItsSamples) {
  const Scene scene = test::scene_from(spring_points(10.0));
  const Registry registry = Registry::load();
  const std::string path = trajectory_path("reference");
  const RunRecord run = run_writing(registry.reference(), scene, scene.sample, path);
  ASSERT_EQ(run.status, RunStatus::Ok) << run.reason;
  const test::TrajectoryCsv file = test::read_trajectory(path);
  const std::size_t bodies = scene.bodies.size();
  ASSERT_EQ(file.rows.size(), bodies * run.trajectory.states.size());
  for (std::size_t j = 0; j < run.trajectory.states.size(); ++j)
    for (std::size_t b = 0; b < bodies; ++b) {
      const std::string at = "sample " + std::to_string(j);
      EXPECT_EQ(file.rows[j * bodies + b].t, run.trajectory.times[j]) << at;
      EXPECT_EQ(file.rows[j * bodies + b].t, static_cast<double>(j) * scene.sample) << at;
      expect_state(file.rows[j * bodies + b], run.trajectory.states[j][b], at);
    }
}

TEST(TrajectoryFile, RotationColumnsWhereABodyCanTurnHoldItsOrientationAndSpin) {
  const Scene scene = test::scene_from(test::spinning_ball_case(3.0, 30.0));
  const double dt = scene.dt.front();
  const std::string path = trajectory_path("rotation");
  const RunRecord run = run_writing(kExplicitEuler, scene, dt, path);
  ASSERT_EQ(run.status, RunStatus::Ok) << run.reason;
  const test::TrajectoryCsv file = test::read_trajectory(path);
  EXPECT_EQ(file.header, "t,body,x,y,z,vx,vy,vz,qw,qx,qy,qz,wx,wy,wz");
  EXPECT_TRUE(file.complete);
  const std::size_t per_sample = static_cast<std::size_t>(scene.steps_per_sample(dt));
  ASSERT_EQ(file.rows.size(), (run.trajectory.states.size() - 1) * per_sample + 1);
  for (std::size_t j = 0; j < run.trajectory.states.size(); ++j)
    expect_state(file.rows[j * per_sample], run.trajectory.states[j][0],
                 "sample " + std::to_string(j));
  // The ball turned: its spin is in the rows, not a column of zeros.
  EXPECT_NE(file.rows.back().values[12], 0.0);
  EXPECT_NE(file.rows.back().values[6], file.rows.front().values[6]);
}

TEST(TrajectoryFile, ADivergedRunEndsAtTheSampleItWasStoppedAt) {
  // Explicit Euler at 0.05 s on a spring of 10^4 N/m grows sevenfold a step.
  const Scene scene = test::scene_from(spring_points(1e4));
  const std::string path = trajectory_path("diverged");
  const RunRecord run = run_writing(kExplicitEuler, scene, 0.05, path);
  ASSERT_EQ(run.status, RunStatus::Diverged) << run.reason;
  ASSERT_TRUE(run.diverged_at);
  const test::TrajectoryCsv file = test::read_trajectory(path);
  ASSERT_FALSE(file.rows.empty());
  EXPECT_EQ(file.rows.back().t, *run.diverged_at);
  EXPECT_LT(file.rows.back().t, scene.duration);
  EXPECT_EQ(file.rows.size(), scene.bodies.size() * static_cast<std::size_t>(run.steps + 1));
}

TEST(TrajectoryFile, ARunThatNeverHadAStateWritesNoFile) {
  // Two balls touching at the start: the reference has no exact answer (unsupported).
  const Scene scene = test::scene_from(test::kStackedBalls);
  const Registry registry = Registry::load();
  const std::string path = trajectory_path("no_state");
  const RunRecord run = run_writing(registry.reference(), scene, scene.sample, path);
  ASSERT_EQ(run.status, RunStatus::Unsupported);
  EXPECT_FALSE(std::filesystem::exists(path));
}

TEST(TrajectoryFile, AFileThatCannotBeWrittenSaysWhy) {
  const Scene scene = test::scene_from(spring_points(10.0));
  for (const auto& [path, reason] :
       {std::pair<std::string, std::string>{"/dev/full", "No space left on device"},
        {test::fresh_dir("trajectory_nowhere") + "/no/such/folder.csv",
         "No such file or directory"}}) {
    TrajectoryWriter writer(path, scene);
    const RunRecord run = run_accuracy(kExplicitEuler, scene, 0.05, false, &writer);
    EXPECT_EQ(run.status, RunStatus::Ok);
    EXPECT_NE(writer.close().find(reason), std::string::npos) << path;
  }
}

}  // namespace
}  // namespace bb
