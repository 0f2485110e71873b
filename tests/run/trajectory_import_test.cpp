// A program's trajectory brought in (run --trajectory NAME@DT=FILE) is judged as a backend:
// every built-in backend's own trajectories, written with --trajectories and read back as
// import/NAME, give its row again (status, every error metric, every observable, the order),
// on small cases with contacts, springs and rotation; the reference's file, with rows at the
// samples only, gives no error and says which observables need the steps.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "run/case_runner.hpp"
#include "run/import_backend.hpp"
#include "run/trajectory_names.hpp"
#include "study/load_case.hpp"
#include "study/metric_names.hpp"
#include "support/program.hpp"
#include "support/test_support.hpp"

namespace bb {
namespace {

namespace fs = std::filesystem;

/// A ball dropped on a bouncy ground in 2D: contacts, apexes.
constexpr const char* kBounce = R"(name = "bounce"
dims = 2
duration = 1.5
sample = 0.05
dt = [0.01, 0.005, 0.0025]
report_dt = 0.005
[ground]
restitution = 0.8
[[body]]
name = "ball"
radius = 0.2
mass = 1.0
position = [0.0, 1.0, 0.0]
velocity = [0.5, 0.0, 0.0]
[[observe]]
kind = "bounce_apex"
body = "ball"
n = 1
[[observe]]
kind = "contact_time"
body = "ball"
n = 1
[[observe]]
kind = "final_speed"
body = "ball"
)";

/// Two points on an undamped spring, without gravity: springs, a period.
constexpr const char* kSpring = R"(name = "spring"
dims = 2
duration = 1.5
sample = 0.05
dt = [0.01, 0.005, 0.0025]
report_dt = 0.005
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
position = [0.55, 0.0, 0.0]
[[spring]]
bodies = ["left", "right"]
stiffness = 100.0
damping = 0.0
rest_length = 1.0
[[observe]]
kind = "period"
body = "left"
[[observe]]
kind = "max_stretch"
)";

/// A box spun about its middle axis in 3D, without gravity: rotation, its flips.
constexpr const char* kSpin = R"(name = "spin"
dims = 3
duration = 1.5
sample = 0.05
dt = [0.01, 0.005, 0.0025]
report_dt = 0.005
gravity = [0.0, 0.0, 0.0]
[[body]]
name = "box"
shape = "box"
half_extents = [0.05, 0.2, 0.4]
mass = 1.0
position = [0.0, 0.0, 0.0]
angular_velocity = [0.06, 6.0, 0.0]
[[observe]]
kind = "flips"
body = "box"
[[observe]]
kind = "final_speed"
body = "box"
)";

/// A run's row of `results`: `backend` at `dt`, or nullptr.
const RunRecord* row_of(const CaseResults& results, const std::string& backend, double dt) {
  for (const RunRecord& r : results.runs)
    if (r.backend == backend && r.dt && *r.dt == dt) return &r;
  return nullptr;
}

/// `a` and `b` alike to rounding (both absent, or within 1e-9 relative of each other).
bool alike(std::optional<double> a, std::optional<double> b) {
  if (!a || !b) return !a && !b;
  if (std::isnan(*a) || std::isnan(*b)) return std::isnan(*a) && std::isnan(*b);
  return std::abs(*a - *b) <= 1e-9 * std::max({std::abs(*a), std::abs(*b), 1e-300});
}

/// Every built-in backend of `case_text`, written and read back, gives its own row again;
/// returns how many of the rows compared were diverged.
int expect_round_trip(const std::string& case_text) {
  const Scene scene = test::scene_from(case_text);
  const Registry registry = Registry::load();
  // A folder per test: two tests of one scene run at once under ctest -j2.
  const std::string folder =
      test::fresh_dir("import_round_trip_" +
                      std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
  fs::create_directories(folder);
  RunOptions written;
  written.cost = false;
  written.trajectories = folder;
  const CaseResults first = run_case(scene, registry, written);

  // Each backend's files, read back as import/<its file's name before the '@'>.
  std::vector<TrajectoryImport> given;
  std::map<std::string, std::string> imported_as;
  for (const RunRecord& run : first.runs) {
    const std::string file = folder + "/" + trajectory_file_name(run.backend, run.dt);
    if (!fs::exists(file)) continue;
    const std::string name = file.substr(folder.size() + 1, file.find('@') - folder.size() - 1);
    given.push_back({name, *run.dt, file});
    imported_as[run.backend] = kImportPrefix + name;
  }
  EXPECT_GE(imported_as.size(), 4u) << "at least the course integrators";
  RunOptions read;
  read.cost = false;
  read.backends = {"reference"};
  read.imports = load_imports(scene, given);
  const CaseResults second = run_case(scene, registry, read);

  int compared = 0, diverged = 0;
  for (const RunRecord& run : first.runs) {
    const auto found = imported_as.find(run.backend);
    if (found == imported_as.end()) continue;
    const RunRecord* back = row_of(second, found->second, *run.dt);
    if (back == nullptr) {
      ADD_FAILURE() << "no row of " << found->second;
      continue;
    }
    const std::string what = run.backend + " at " + std::to_string(*run.dt) + ": ";
    // An engine's cap is the engine's word, not in its states: the import ran to the end.
    const RunStatus expected = run.status == RunStatus::Capped ? RunStatus::Ok : run.status;
    EXPECT_EQ(status_name(back->status), status_name(expected)) << what << back->reason;
    if (run.status == RunStatus::Diverged) {
      EXPECT_EQ(back->diverged_at, run.diverged_at) << what;
    }
    EXPECT_EQ(back->errors.has_value(), run.errors.has_value()) << what;
    for (const std::string& metric : error_metric_names()) {
      EXPECT_TRUE(alike(metric_value(*back, metric), metric_value(run, metric)))
          << what << metric << " " << metric_value(*back, metric).value_or(-1) << " vs "
          << metric_value(run, metric).value_or(-1);
    }
    EXPECT_EQ(back->observables.size(), run.observables.size()) << what;
    for (std::size_t i = 0; i < run.observables.size() && i < back->observables.size(); ++i)
      EXPECT_TRUE(alike(back->observables[i].measured.value, run.observables[i].measured.value))
          << what << run.observables[i].name << ": " << back->observables[i].measured.note;
    ++compared;
    diverged += run.status == RunStatus::Diverged;
  }
  EXPECT_GE(compared, 12) << "the course integrators at three steps";
  // The order of convergence comes from the same errors.
  for (const auto& [backend, as] : imported_as) {
    const auto order = first.order.find(backend);
    const auto again = second.order.find(as);
    EXPECT_EQ(order != first.order.end(), again != second.order.end()) << backend;
    if (order != first.order.end() && again != second.order.end()) {
      EXPECT_NEAR(again->second, order->second, 1e-9) << backend;
    }
  }
  return diverged;
}

TEST(TrajectoryImport, EveryBackendsOwnTrajectoryGivesItsRowAgainWithContacts) {
  expect_round_trip(kBounce);
}

TEST(TrajectoryImport, EveryBackendsOwnTrajectoryGivesItsRowAgainWithSprings) {
  expect_round_trip(kSpring);
}

TEST(TrajectoryImport, EveryBackendsOwnTrajectoryGivesItsRowAgainWithRotation) {
  expect_round_trip(kSpin);
}

// A spring stiff enough for explicit Euler to diverge at every step of the sweep: its
// files end where the run was stopped, and read back they diverge there again.
TEST(TrajectoryImport, ADivergedRunsTrajectoryGivesTheSameDivergedRow) {
  std::string stiff = kSpring;
  stiff.replace(stiff.find("stiffness = 100.0"), 17, "stiffness = 20000.0");
  EXPECT_GE(expect_round_trip(stiff), 3);
}

TEST(TrajectoryImport, TheReferencesSamplesGiveNoErrorAndNoObservableThatNeedsTheSteps) {
  const Scene scene = test::scene_from(kBounce);
  const Registry registry = Registry::load();
  const std::string folder = test::fresh_dir("import_reference_samples");
  fs::create_directories(folder);
  RunOptions written;
  written.cost = false;
  written.backends = {"reference"};
  written.trajectories = folder;
  const CaseResults first = run_case(scene, registry, written);
  RunOptions read;
  read.cost = false;
  read.backends = {"reference"};
  read.imports = load_imports(scene, {{"ref", 0.01, folder + "/reference.csv"}});
  const CaseResults second = run_case(scene, registry, read);
  const RunRecord* row = row_of(second, "import/ref", 0.01);
  ASSERT_NE(row, nullptr);
  ASSERT_EQ(row->status, RunStatus::Ok) << row->reason;
  ASSERT_TRUE(row->errors);
  for (const std::string& metric : error_metric_names())
    EXPECT_EQ(metric_value(*row, metric), 0.0) << metric;
  ASSERT_EQ(row->observables.size(), 3u);
  // bounce_apex and contact_time need the steps; final_speed is the last sample's.
  EXPECT_FALSE(row->observables[0].measured.value);
  EXPECT_EQ(row->observables[0].measured.note, kSamplesOnlyNote);
  EXPECT_FALSE(row->observables[1].measured.value);
  EXPECT_EQ(row->observables[1].measured.note, kSamplesOnlyNote);
  EXPECT_EQ(row->observables[2].measured.value, first.reference_run.observables[2].measured.value);
  // Not timed: without cost_ns the program's cost is not measured.
  EXPECT_FALSE(row->cost);
}

}  // namespace
}  // namespace bb
