// What every engine's spring backends share, whichever way they build springs: the
// by-hand variant `<engine>/force` takes part only in spring scenes, every run names how
// its springs were built, and an anchored cloth particle stays where it started.
// Backends whose plugins were not built are skipped.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "run/accuracy_run.hpp"
#include "support/engine_support.hpp"
#include "support/test_support.hpp"

namespace bb {
namespace {

using test::engine;
using test::takes_part;
using test::text_setting;

class SpringVariants : public ::testing::TestWithParam<std::string> {};

TEST_P(SpringVariants, TheForceVariantTakesPartOnlyOnSpringScenes) {
  const std::string force = std::string(GetParam()) + "/force";
  BB_SKIP_IF_MISSING(test::not_built({force}));
  EXPECT_FALSE(takes_part(force, test::bundled_case("drag_fall")));
  EXPECT_TRUE(takes_part(force, test::bundled_case("spring_pair")));
  EXPECT_TRUE(takes_part(GetParam(), test::bundled_case("drag_fall")));
}

TEST_P(SpringVariants, BothWaysNameHowTheirSpringsAreBuilt) {
  const Scene scene = test::bundled_case("spring_pair_damped");
  for (const std::string& name : {std::string(GetParam()), std::string(GetParam()) + "/force"}) {
    if (engine(name) == nullptr) continue;
    const RunRecord run = run_accuracy(*engine(name), scene, scene.report_dt);
    ASSERT_EQ(run.status, RunStatus::Ok) << name << ": " << run.reason;
    EXPECT_FALSE(text_setting(run.engine_settings, "springs").empty()) << name;
  }
}

INSTANTIATE_TEST_SUITE_P(Engines, SpringVariants,
                         ::testing::ValuesIn(test::engines_with_force_build()),
                         [](const auto& info) { return test::test_name(info.param); });

// Every spring backend on the stiff cloth, at the coarsest of the case's steps at which its
// run goes to the end (the springs applied by hand blow up at the report's 1/60 s: the case's
// lesson; the finest step costs 16 times the steps of 1/60 s): the anchors do not move (a
// float engine stores the start rounded to float).
TEST(SpringBackends, AnchoredClothParticlesDoNotMove) {
  const Scene scene = test::bundled_case("cloth_stiff");
  const std::size_t anchor = static_cast<std::size_t>(scene.body_index("p3_0"));
  ASSERT_TRUE(scene.bodies[anchor].fixed);
  const Vec3 start = scene.bodies[anchor].position;
  int ran = 0;
  for (const char* name : {"bullet", "bullet-float", "bullet/force", "bullet-softbody", "box2d",
                           "box2d/force", "ode", "ode/force"}) {
    if (engine(name) == nullptr) continue;
    RunRecord run;
    for (const double dt : scene.dt)
      if ((run = run_accuracy(*engine(name), scene, dt)).status == RunStatus::Ok) break;
    ASSERT_EQ(run.status, RunStatus::Ok) << name << " at every step: " << run.reason;
    ASSERT_FALSE(run.trajectory.states.empty()) << name;
    double moved = 0.0;
    for (const State& s : run.trajectory.states)
      moved = std::max(moved, (s[anchor].position - start).norm());
    const bool single =
        std::string(name) == "bullet-float" || std::string(name).rfind("box2d", 0) == 0;
    EXPECT_LE(moved, single ? 1e-6 * (1.0 + start.norm()) : 0.0) << name;
    ++ran;
  }
  BB_SKIP_IF_MISSING(ran == 0 ? "no engine plugin was built" : "");
}

}  // namespace
}  // namespace bb
