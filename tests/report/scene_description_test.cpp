// Every parameter of a scene that changes its physics is on its page: each spring's k,
// damping and rest length, the grid's rule, the waves' formula, each hinge's axis, each
// impulse, each constant push and how each body starts turned, for every bundled case.
#include "report/scene_description.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <filesystem>

#include "report/format.hpp"
#include "study/load_case.hpp"
#include "support/test_support.hpp"

namespace bb {
namespace {

/// Every number and vector of `scene` that its physics reads beyond the bodies' start, as
/// the page writes it.
std::vector<std::string> parameters_of(const Scene& scene) {
  std::vector<std::string> wanted;
  const auto number = [&](double v) { wanted.push_back(fmt::format("{:g}", v)); };
  const auto vector = [&](const Vec3& v, int dims) { wanted.push_back(format_vector(v, dims)); };
  for (const Spring& s : scene.springs)
    if (!scene.grid) {
      number(s.stiffness);
      number(s.damping);
      number(s.rest_length);
    }
  if (const std::optional<Grid>& g = scene.grid) {
    for (double v : {g->stiffness, g->damping, g->spacing, g->mass}) number(v);
    vector(g->origin, scene.dims);
  }
  if (const std::optional<Waves>& w = scene.waves)
    for (double v : {w->amplitude, w->wavenumber, w->speed, w->level, w->from, w->to}) number(v);
  for (const Hinge& h : scene.hinges) {
    vector(h.anchor, scene.dims);
    vector(h.axis, 3);
  }
  for (const Impulse& i : scene.impulses) {
    number(i.time);
    vector(i.impulse, scene.dims);
    if (i.point) vector(*i.point, scene.dims);
  }
  for (const Body& b : scene.bodies) {
    if (!b.force.isZero()) vector(b.force, scene.dims);
    if (!b.torque.isZero()) vector(b.torque, 3);
    if (!b.wind_force.isZero()) vector(b.wind_force, scene.dims);
  }
  return wanted;
}

TEST(SceneDescription, EveryBundledCaseStatesEveryParameterOfItsPhysics) {
  int checked = 0;
  for (const auto& entry : std::filesystem::directory_iterator(test::source_path("cases"))) {
    if (entry.path().extension() != ".toml") continue;
    const Scene scene = load_case(entry.path().string());
    const std::string page = describe_scene(scene);
    for (const std::string& p : parameters_of(scene)) {
      EXPECT_NE(page.find(p), std::string::npos) << scene.name << ": " << p << "\n" << page;
      ++checked;
    }
  }
  EXPECT_GT(checked, 50);
}

TEST(SceneDescription, AHingedPlankSaysWhereItsAxisIsAndHowItStartsTurned) {
  Scene scene = test::scene_from(R"(name = "plank_on_axis"
dims = 2
duration = 1.0
sample = 0.1
dt = [0.01]
report_dt = 0.01

[[body]]
name = "plank"
shape = "box"
half_extents = [1.0, 0.1, 0.1]
mass = 2.0
position = [1.0, 0.0, 0.0]
angle = 30.0

[[hinge]]
body = "plank"
anchor = [0.25, 0.0, 0.0]
)");
  const std::string page = describe_scene(scene);
  EXPECT_NE(page.find("(0.25, 0)"), std::string::npos) << page;
  EXPECT_NE(page.find("30 deg"), std::string::npos) << page;
}

TEST(SceneDescription, AGridIsOneLineAndItsParticlesAreFolded) {
  Scene scene = test::scene_from(R"(name = "rope"
dims = 2
duration = 1.0
sample = 0.1
dt = [0.01]
report_dt = 0.01

[grid]
size = [5, 1]
spacing = 0.5
mass = 0.2
neighbours = 4
stiffness = 300.0
damping = 0.7
origin = [0.0, 2.0, 0.0]
)");
  const std::string page = describe_scene(scene);
  EXPECT_NE(page.find("k = 300 N/m"), std::string::npos) << page;
  EXPECT_NE(page.find("damping 0.7 N s/m"), std::string::npos) << page;
  const std::size_t folded = page.find("<details>");
  ASSERT_NE(folded, std::string::npos) << page;
  EXPECT_GT(page.find("| p0_0"), folded) << page;
}

}  // namespace
}  // namespace bb
