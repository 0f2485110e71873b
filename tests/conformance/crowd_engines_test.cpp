// many_beachballs, the seed's crowd of 30 beach balls in a box: whatever each backend does
// to their spins and however the pile settles, every ball stays inside the box (between the
// walls' inner faces, above the floor, to within the overlap a step allows) and in the
// scene's plane at report_dt (a soft contact, MuJoCo's, lets a ball sink deeper, by its
// speed times the contact's time constant). The engines keep a 2D scene in the x-y plane with their
// own mechanism (Bullet's linear and angular factors, ODE's plane-2D joint), recorded under
// plane_2d.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "run/accuracy_run.hpp"
#include "run/case_loading.hpp"
#include "support/engine_support.hpp"
#include "support/test_support.hpp"

namespace bb {
namespace {

using test::text_setting;

/// The backend called `name` among those that take part in `scene` (null when it does not),
/// with the set that owns the course variants: the pointer lives as long as the set.
struct Found {
  BackendSet set;
  const Backend* backend = nullptr;
};
Found find_backend(const Scene& scene, const std::string& name) {
  Found found{backends_for(scene, test::registry())};
  for (const Backend* b : found.set.all)
    if (b->name() == name) found.backend = b;
  return found;
}

class CrowdEngines : public ::testing::TestWithParam<std::string> {};

/// The course's two crowd rules and every rigid engine the adapters describe.
std::vector<std::string> crowd_backends() {
  std::vector<std::string> out = {"course/semi-implicit-euler+kinematic",
                                  "course/semi-implicit-euler+shared"};
  for (const std::string& e : test::rigid_engines()) out.push_back(e);
  return out;
}

TEST_P(CrowdEngines, EveryBallStaysInTheBoxAndThePlane) {
  const Scene scene = load_case(test::source_path("cases/many_beachballs.toml"));
  ASSERT_EQ(scene.dims, 2);
  const Found found = find_backend(scene, GetParam());
  const Backend* backend = found.backend;
  if (backend == nullptr && !test::described_but_not_built(GetParam()))
    GTEST_SKIP() << GetParam() << " is not among this scene's backends";
  BB_SKIP_IF_MISSING(test::not_built({GetParam()}));
  for (Feature f : scene.features().missing_from(backend->supports()))
    GTEST_SKIP() << GetParam() << " does not simulate " << feature_name(f)
                 << " (its description says so)";
  const RunRecord run = run_accuracy(*backend, scene, scene.report_dt);
  ASSERT_EQ(run.status, RunStatus::Ok) << run.reason;
  const Body& wall = scene.bodies[scene.body_index("right_wall")];
  const double inner = wall.position.x() - wall.half_extents.x();
  double worst = 0.0;    // the furthest any ball's surface went past a wall or the floor, m
  double off_plane = 0;  // the largest |z| of any ball, m
  double fastest = 0.0;  // m/s
  for (const State& s : run.trajectory.states)
    for (std::size_t i = 0; i < s.size(); ++i) {
      const Body& b = scene.bodies[i];
      if (b.fixed) continue;
      worst = std::max(
          {worst, std::abs(s[i].position.x()) + b.radius - inner, b.radius - s[i].position.y()});
      off_plane = std::max(off_plane, std::abs(s[i].position.z()));
      fastest = std::max(fastest, s[i].velocity.norm());
    }
  // A soft contact (one with a time constant tau, MuJoCo's) lets a body at speed v sink
  // about v tau before it turns it back: a spring of natural frequency 1 / tau.
  const double tau = test::number_setting(run.engine_settings, "contact_time");
  const double allowed = std::isnan(tau) ? 0.1 : fastest * tau;
  EXPECT_LT(worst, allowed) << GetParam();
  EXPECT_LT(off_plane, 1e-9) << GetParam();
}

INSTANTIATE_TEST_SUITE_P(Engines, CrowdEngines, ::testing::ValuesIn(crowd_backends()),
                         test::param_test_name);

// One ball thrown in the plane, as a 2D scene and (dims replaced) as a 3D one.
const char* kThrow = R"(name = "throw"
dims = DIMS
duration = 0.5
sample = 0.1
dt = [0.01]
report_dt = 0.01

[[body]]
name = "ball"
radius = 0.2
mass = 1.0
position = [0.0, 2.0, 0.0]
velocity = [1.0, 2.0, 0.0]
)";

/// kThrow with `dims` dimensions.
Scene throw_scene(int dims) {
  std::string text = kThrow;
  text.replace(text.find("DIMS"), 4, std::to_string(dims));
  return test::scene_from(text);
}

TEST(CrowdEngines, EngineSettingsSayHowA2DSceneIsHeldInThePlane) {
  const Scene flat = throw_scene(2), solid = throw_scene(3);
  // Every 3D engine holds a 2D scene in the plane its own way, named as its description
  // declares ("plane_2d").
  for (const std::string& name : test::rigid_engines_with(Feature::ThreeD)) {
    SCOPED_TRACE(name);
    const EngineDescription& described = *test::description_of(name);
    ASSERT_TRUE(described.names_in_settings.count("plane_2d")) << name;
    const std::string& mechanism = described.names_in_settings.at("plane_2d");
    const Found found = find_backend(flat, name);
    const Backend* backend = found.backend;
    if (backend == nullptr) continue;  // not built
    const RunRecord in_2d = run_accuracy(*backend, flat, flat.report_dt);
    ASSERT_EQ(in_2d.status, RunStatus::Ok) << in_2d.reason;
    EXPECT_NE(text_setting(in_2d.engine_settings, "plane_2d").find(mechanism), std::string::npos);
    const RunRecord in_3d = run_accuracy(*backend, solid, solid.report_dt);
    ASSERT_EQ(in_3d.status, RunStatus::Ok) << in_3d.reason;
    EXPECT_EQ(text_setting(in_3d.engine_settings, "plane_2d"), "none (3D scene)");
  }
}

}  // namespace
}  // namespace bb
