// A claim must be able to fail on the physics it is about: each bundled case below is run
// with the one thing its sentence rests on broken, and the claim about it must then fail
// (where, before, a claim read a speed without its direction, or compared two balls that
// integrate one equation, it held whatever the physics did).
#include <gtest/gtest.h>

#include "run/case_runner.hpp"
#include "run/claims.hpp"
#include "support/test_support.hpp"

namespace bb {
namespace {

/// The bundled case `name` with each `from` in its text replaced by `to`.
std::string mutated(const std::string& name,
                    const std::vector<std::pair<std::string, std::string>>& edits) {
  std::string text = test::bytes(test::source_path("cases/" + name + ".toml"));
  for (const auto& [from, to] : edits) {
    const std::size_t at = text.find(from);
    if (at == std::string::npos) throw std::runtime_error(name + " has no '" + from + "'");
    text.replace(at, from.size(), to);
  }
  return text;
}

/// The verdict of `backend` on the claim whose text starts with `claim`, the case `text` run
/// by the reference and `backend` at report_dt only.
std::string verdict_of(const std::string& text, const std::string& backend,
                       const std::string& claim) {
  static Scene scene;  // the results point into it
  scene = test::scene_from(text);
  RunOptions options;
  options.backends = {backend};
  options.dts = {scene.report_dt};
  options.cost = false;
  options.isolation = false;
  options.sweep = false;
  const CaseResults results = run_case(scene, Registry::load(), options);
  for (const ClaimResult& c : judge_claims(results))
    if (c.claim->text.rfind(claim, 0) == 0)
      for (const ClaimVerdict& v : c.verdicts)
        if (v.backend == backend) return v.verdict;
  throw std::runtime_error("no verdict of " + backend + " on '" + claim + "'");
}

// Bounces back: the light ball's velocity after the hit has a direction. With the masses
// swapped it goes on forward at the very speed it would have come back with,
// (m1 - m2) / (m1 + m2) v: only the sign along the contact normal tells the two apart.
TEST(ClaimMutations, ABallThatGoesOnForwardDoesNotBounceBack) {
  const std::string claim = "An elastic hit keeps momentum and energy: the 1 g ball bounces back";
  const std::string text = test::bytes(test::source_path("cases/mass_ratio_1000.toml"));
  EXPECT_EQ(verdict_of(text, "course/rk4", claim), "holds");
  const std::string swapped = mutated("mass_ratio_1000", {{"mass = 0.001", "mass = 1.0!"},
                                                          {"mass = 1.0\n", "mass = 0.001\n"},
                                                          {"mass = 1.0!", "mass = 1.0"}});
  EXPECT_EQ(verdict_of(swapped, "course/rk4", claim), "fails");
}

// Equal masses exchange velocities only in an elastic hit: a plastic one sends both on
// together, and both the exchange and the kept energy must fail.
TEST(ClaimMutations, APlasticHitExchangesNothing) {
  const std::string plastic = mutated("equal_masses", {{"restitution = 1.0", "restitution = 0.0"}});
  EXPECT_EQ(verdict_of(plastic, "course/semi-implicit-euler",
                       "Equal masses in an elastic hit exchange velocities: the left"),
            "fails");
  EXPECT_EQ(verdict_of(plastic, "course/semi-implicit-euler",
                       "Equal masses in an elastic hit exchange velocities: the right"),
            "fails");
  EXPECT_EQ(verdict_of(plastic, "course/semi-implicit-euler", "An elastic collision also keeps"),
            "fails");
}

// Beach balls fall together because their mass grows as r^2, like their area: a large ball
// whose mass grows as r^3 does not.
TEST(ClaimMutations, ShellsWhoseMassDoesNotGrowAsRSquaredDoNotFallTogether) {
  const std::string claim = "Beach balls of every size fall at the same speed";
  const std::string text = test::bytes(test::source_path("cases/beachball_shells.toml"));
  EXPECT_EQ(verdict_of(text, "course/rk4", claim), "holds");
  EXPECT_EQ(
      verdict_of(mutated("beachball_shells", {{"mass = 1.6", "mass = 6.4"}}), "course/rk4", claim),
      "fails");
}

// The larger ball reaches its final speed later: not a fact of every fall. Make the
// "elephant" the small one and it gets there first.
TEST(ClaimMutations, TheSmallerBallReachesItsFinalSpeedFirst) {
  const std::string claim = "The larger ball reaches its final speed later";
  const std::string text = test::bytes(test::source_path("cases/drag_fall.toml"));
  EXPECT_EQ(verdict_of(text, "course/rk4", claim), "holds");
  const std::string small = mutated("drag_fall", {{"radius = 1.0", "radius = 0.05"},
                                                  {"mass = 83.775804095727830", "mass = 0.01"}});
  EXPECT_EQ(verdict_of(small, "course/rk4", claim), "fails");
}

// Three beachballs 2: drag is divided by the mass, so the heavier right ball slows less.
// Swap the masses and the middle one no longer slows more.
TEST(ClaimMutations, DragDividedByTheMassSlowsTheLightBallMore) {
  const std::string claim = "Three beachballs 2: the middle ball slows down fast";
  const std::string text = test::bytes(test::source_path("cases/three_beachballs_2.toml"));
  EXPECT_EQ(verdict_of(text, "course/rk4", claim), "holds");
  const std::string swapped = mutated(
      "three_beachballs_2", {{"mass = 1.0\nposition = [0.0", "mass = 5.0\nposition = [0.0"},
                             {"mass = 5.0\nposition = [3.0", "mass = 1.0\nposition = [3.0"}});
  EXPECT_EQ(verdict_of(swapped, "course/rk4", claim), "fails");
}

// Verlet keeps a spring's oscillation its size: the claim is read on the energy at every
// sample against the reference's, not on the largest stretch (reached at the start, that
// cannot see an oscillation die away). Judged on a method that does not keep the size,
// explicit Euler, the same claim must fail.
TEST(ClaimMutations, AnOscillationThatChangesItsSizeDoesNotKeepIt) {
  const std::string claim = "Verlet integration is all a spring needs: its oscillation keeps";
  const std::string text = test::bytes(test::source_path("cases/spring_pair.toml"));
  EXPECT_EQ(verdict_of(text, "course/velocity-verlet", claim), "holds");
  // Explicit Euler gains energy every step; at 1/60 s it blows up, which counts as failing.
  const std::string euler =
      mutated("spring_pair", {{"left = \"course/velocity-verlet:energy_max\"",
                               "left = \"course/explicit-euler:energy_max\""}});
  EXPECT_EQ(verdict_of(euler, "course/explicit-euler", claim).rfind("fails", 0), 0u);
}

// Magnus: more velocity, more force. With a force that ignores the velocity (no Magnus
// coefficient at all, here) the fast and the slow ball end at one height.
TEST(ClaimMutations, WithoutTheMagnusForceSpeedAndSpinLiftNothing) {
  const std::string faster = "Magnus: the faster ball";
  const std::string spin = "Magnus: the ball with more spin";
  const std::string text = test::bytes(test::source_path("cases/magnus_force.toml"));
  EXPECT_EQ(verdict_of(text, "course/rk4", faster), "holds");
  EXPECT_EQ(verdict_of(text, "course/rk4", spin), "holds");
  std::string none = text;
  for (std::size_t at; (at = none.find("magnus = 0.003")) != std::string::npos;)
    none.replace(at, 14, "magnus = 0.0");
  EXPECT_EQ(verdict_of(none, "course/rk4", faster), "fails");
  EXPECT_EQ(verdict_of(none, "course/rk4", spin), "fails");
}

}  // namespace
}  // namespace bb
