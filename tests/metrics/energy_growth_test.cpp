// Growth that compounds is told from drift that adds and from a bounded swing, on synthetic
// energy histories: any power of time is drift, an exponential compounds, a runaway capped
// by the motion's nonlinearity is still a runaway.
#include "metrics/energy_growth.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>

namespace bb {
namespace {

/// The running maximum of `rise(t)` (t in [0, 1] of the run) at the ends of 16 windows of a
/// run of `steps` steps, on a scene whose energy scale is `scale`.
EnergyHistory history(const std::function<double(double)>& rise, double scale, long steps = 1600) {
  EnergyHistory h;
  h.scale = scale;
  double largest = 0.0;
  for (long n = 1; n <= steps; ++n) {
    largest = std::max(largest, rise(static_cast<double>(n) / static_cast<double>(steps)));
    if (n % std::max(1L, steps / kGrowthWindows) == 0 && h.level.size() < kGrowthWindows) {
      h.level.push_back(largest);
      h.steps.push_back(n);
    }
  }
  return h;
}

TEST(EnergyGrowth, AnyPowerOfTimeIsDriftThatAdds) {
  for (double p : {1.0, 1.1, 2.0, 3.0, 5.0}) {
    const GrowthVerdict v =
        judge_growth(history([p](double t) { return std::pow(t, p); }, 1.0), 1.02);
    EXPECT_EQ(v.growth, Growth::Drift) << p << ": " << v.reason;
    EXPECT_TRUE(v.stable);
    EXPECT_NE(v.reason.find("drift that adds"), std::string::npos) << v.reason;
  }
}

TEST(EnergyGrowth, AnExponentialCompoundsEvenWhenSlow) {
  // lambda T from 0.5 (the energy grows by 65 percent over the run) to 8; each ends at a
  // tenth of the scene's energy scale.
  for (double lambda_t : {0.5, 2.0, 8.0}) {
    const double size = 1e5 / std::expm1(lambda_t);
    const GrowthVerdict v =
        judge_growth(history([=](double t) { return size * std::expm1(lambda_t * t); }, 1e6), 1.02);
    EXPECT_EQ(v.growth, Growth::Compounds) << lambda_t << ": " << v.reason;
    EXPECT_FALSE(v.stable);
    EXPECT_NE(v.reason.find("compounding"), std::string::npos) << v.reason;
  }
}

TEST(EnergyGrowth, TheGrowthFactorSetsHowFastCompoundingMustBe) {
  const auto slow = history([](double t) { return std::expm1(0.5 * t); }, 10.0);
  EXPECT_EQ(judge_growth(slow, 1.02).growth, Growth::Compounds);
  EXPECT_EQ(judge_growth(slow, 1.5).growth, Growth::Drift);
}

// Semi-implicit Euler just below 2 / omega swings its energy far above its start within a
// period, and no further: bounded, however large.
TEST(EnergyGrowth, ASwingThatRepeatsItselfIsBounded) {
  const GrowthVerdict v = judge_growth(
      history([](double t) { return 50.0 * std::pow(std::sin(400.0 * t), 2); }, 2.5), 1.02);
  EXPECT_EQ(v.growth, Growth::Bounded) << v.reason;
  EXPECT_TRUE(v.stable);
}

// A spring folding through itself: the energy compounds from its start, then the folded
// motion caps it far above anything the scene's physics can trade.
TEST(EnergyGrowth, ARunawayCappedByTheNonlinearityIsNoBound) {
  const auto folded = [](double t) { return std::min(0.5 * std::expm1(12.0 * t), 70.0); };
  const GrowthVerdict v = judge_growth(history(folded, 2.5), 1.02);
  EXPECT_EQ(v.growth, Growth::Runaway) << v.reason;
  EXPECT_FALSE(v.stable);
  EXPECT_NE(v.reason.find("levelled off"), std::string::npos) << v.reason;
}

// The tennis-racket wobble amplifies a method's energy error until the spin has moved to
// the axis of least inertia, where |L|^2 / (2 I_min) caps the energy: within the scene's
// scale, bounded.
TEST(EnergyGrowth, AnErrorThatGrowsWithAPhysicalWobbleToItsCapIsBounded) {
  const auto wobble = [](double t) { return std::min(1e-6 * std::exp(40.0 * t), 2.75); };
  const GrowthVerdict v = judge_growth(history(wobble, 1.0), 1.02);
  EXPECT_EQ(v.growth, Growth::Bounded) << v.reason;
  EXPECT_NE(v.reason.find("levelled off at 2.75 J"), std::string::npos) << v.reason;
}

// An engine whose joints add energy at the same rate at every step: a rise as t^3, far
// above the scene's energy scale, but drift, not a runaway.
// Explicit Euler at 0.005 s on sproing_2d_4 (its limit is 0.004 s), as measured: the rise
// compounds by about 1.6 per window for most of the run, then slows as the springs'
// geometry stiffens: compounding all the same.
TEST(EnergyGrowth, GrowthThatCompoundsAndThenSlowsCompounds) {
  EnergyHistory h;
  h.scale = 13.1;
  h.level = {0.424, 0.674, 1.11, 1.81, 2.92, 4.90, 8.14, 12.9,
             20.6,  31.2,  45.3, 65.1, 88.9, 117,  154,  189};
  for (long k = 1; k <= 16; ++k) h.steps.push_back(k * 1000 / 16);
  const GrowthVerdict v = judge_growth(h, 1.02);
  EXPECT_EQ(v.growth, Growth::Compounds) << v.reason;
  EXPECT_NE(v.reason.find("quarters 2 and 3"), std::string::npos) << v.reason;
}

// Explicit Euler at 0.0012 s on cloth_stiff (its limit is 0.001 s), as measured: the rise
// doubles every window for half the run, then levels off far below the scene's energy scale
// (the grid's geometry caps it): it compounded.
TEST(EnergyGrowth, GrowthThatCompoundsEarlyAndThenLevelsOffCompounds) {
  EnergyHistory h;
  h.scale = 2.18e4;
  h.level = {0.826, 2.22, 5.21, 10.1, 20.5, 37.2, 63.6, 96.9,
             112,   121,  137,  170,  170,  170,  170,  170};
  for (long k = 1; k <= 16; ++k) h.steps.push_back(k * 4167 / 16);
  const GrowthVerdict v = judge_growth(h, 1.02);
  EXPECT_EQ(v.growth, Growth::Compounds) << v.reason;
  EXPECT_NE(v.reason.find("quarters 1 and 2"), std::string::npos) << v.reason;
}

// A rise that stays flat and then grows as a power of the time since it began is drift.
TEST(EnergyGrowth, DriftThatBeginsLateIsDrift) {
  const auto onset = [](double t) { return 0.5 + (t < 0.2 ? 0.0 : 500.0 * std::pow(t - 0.2, 3)); };
  EXPECT_EQ(judge_growth(history(onset, 1e3), 1.02).growth, Growth::Drift);
}

// Bullet's chain of spring joints: its energy grows as t^3 to many times what the scene can
// put into motion. Drift that never stops adding is unbounded: not stable. The same drift
// within the scale is drift, and stable.
TEST(EnergyGrowth, DriftPastTheScaleIsUnbounded) {
  const auto cubic = [](double t) { return 160.0 * std::pow(t, 3); };
  const GrowthVerdict past = judge_growth(history(cubic, 13.0), 1.02);
  EXPECT_EQ(past.growth, Growth::Runaway) << past.reason;
  EXPECT_FALSE(past.stable);
  EXPECT_NE(past.reason.find("without bound"), std::string::npos) << past.reason;
  const GrowthVerdict within = judge_growth(history(cubic, 1e3), 1.02);
  EXPECT_EQ(within.growth, Growth::Drift) << within.reason;
  EXPECT_TRUE(within.stable);
}

// A rise that grows and then levels off far above the scene's scale (the rope's Verlet at
// 1.04 times its limit: 6e3 J in a 12 J scene) is not bounded near the scene: a runaway.
TEST(EnergyGrowth, ALevelFarAboveTheScaleIsNotBounded) {
  const auto levels = [](double t) { return 6e3 * std::tanh(4.0 * t) * std::tanh(4.0 * t); };
  const GrowthVerdict far = judge_growth(history(levels, 12.0), 1.02);
  EXPECT_FALSE(far.stable) << far.reason;
  EXPECT_EQ(far.growth, Growth::Runaway) << far.reason;
  // The same shape within the scale is bounded.
  EXPECT_TRUE(judge_growth(history(levels, 1e4), 1.02).stable);
}

TEST(EnergyGrowth, TooFewStepsAreJudgedOnARunawayAlone) {
  const GrowthVerdict few =
      judge_growth(history([](double t) { return std::expm1(8 * t); }, 1e3, 10), 1.02);
  EXPECT_TRUE(few.stable);
  EXPECT_NE(few.reason.find("too few steps (10)"), std::string::npos) << few.reason;
  EXPECT_FALSE(
      judge_growth(history([](double t) { return std::expm1(8 * t); }, 100.0, 10), 1.02).stable);
  const auto folded = [](double t) { return std::min(0.5 * std::expm1(12.0 * t), 70.0); };
  EXPECT_EQ(judge_growth(history(folded, 2.5, 8), 1.02).growth, Growth::Runaway);
}

TEST(EnergyGrowth, ARiseWithinNoiseSaysNothing) {
  const GrowthVerdict v =
      judge_growth(history([](double t) { return 1e-10 * std::exp(8 * t); }, 1e3), 1.02);
  EXPECT_EQ(v.growth, Growth::Bounded);
  EXPECT_TRUE(v.reason.empty()) << v.reason;
}

// A hanging chain's explicit Euler: its swing compounds from 0.4 J to 3.6 J while the
// scene's scale, its weight over the whole fall it could make, is 3600 J. A thousandth of
// the scale hid it as noise; it compounds.
TEST(EnergyGrowth, ASwingCompoundingFarBelowTheScaleCompounds) {
  const GrowthVerdict v =
      judge_growth(history([](double t) { return 0.1 * std::exp(3.6 * t); }, 3600.0), 1.02);
  EXPECT_EQ(v.growth, Growth::Compounds) << v.reason;
  EXPECT_FALSE(v.stable);
}

// Energy kept exactly for the first half, then drifting: the quarters with no rise to start
// from are not judged.
TEST(EnergyGrowth, ARiseThatStartsLateIsJudgedFromWhereItStarts) {
  const auto late = [](double t) { return t < 0.5 ? 0.0 : t - 0.5; };
  EXPECT_EQ(judge_growth(history(late, 1.0), 1.02).growth, Growth::Drift);
  const auto late_exp = [](double t) { return t < 0.5 ? 0.0 : std::expm1(8.0 * (t - 0.5)); };
  EXPECT_EQ(judge_growth(history(late_exp, 100.0), 1.02).growth, Growth::Compounds);
}

}  // namespace
}  // namespace bb
