// The order fit recovers exact slopes from points in the asymptotic range only: above the
// rounding floor, below saturation, with local slopes that agree; otherwise it gives no
// order and says why. The floor grows with the number of steps a run takes.
#include "metrics/order.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace bb {
namespace {

/// Points at dt = 1/30, 1/60, ... 1/960 s with the given errors (largest dt first) and floor.
std::vector<ErrorPoint> sweep(const std::vector<double>& errors, double floor = 0.0) {
  std::vector<ErrorPoint> points;
  double dt = 1.0 / 30;
  for (double e : errors) points.push_back({dt, e, floor}), dt /= 2;
  return points;
}

TEST(FitOrder, ExactOnSyntheticPowerLaws) {
  for (double p : {1.0, 2.0, 4.0, 0.5}) {
    std::vector<ErrorPoint> points;
    for (double dt = 1.0 / 30; dt > 1e-3; dt /= 2) points.push_back({dt, 3.7 * std::pow(dt, p)});
    const OrderFit fit = fit_order(points);
    ASSERT_TRUE(fit.slope.has_value()) << p << ": " << fit.reason;
    EXPECT_NEAR(*fit.slope, p, 1e-12);
    EXPECT_EQ(fit.used, static_cast<int>(points.size()));
    EXPECT_EQ(fit.below_floor, 0);
    EXPECT_TRUE(fit.reason.empty());
    ASSERT_EQ(fit.local_slopes.size(), points.size() - 1);
    for (const LocalSlope& s : fit.local_slopes) {
      EXPECT_NEAR(s.slope, p, 1e-12);
      EXPECT_TRUE(s.in_fit);
    }
  }
}

TEST(FitOrder, PointsAtOrBelowTheFloorAreLeftOutAndCounted) {
  // An RK4-like series that flattens at 1e-9 where the reference's own error sits.
  std::vector<ErrorPoint> at_floor, no_floor;
  for (double dt = 1.0 / 30; dt > 1e-3; dt /= 2) {
    const double error = std::max(std::pow(dt, 4), 1e-9);
    at_floor.push_back({dt, error, 2e-9});
    no_floor.push_back({dt, error, 0.0});
  }
  const OrderFit fit = fit_order(at_floor);
  EXPECT_NEAR(*fit.slope, 4.0, 1e-12);
  EXPECT_EQ(fit.below_floor, 3);  // 1/240, 1/480 and 1/960: their error is the 1e-9 plateau
  EXPECT_EQ(fit.used + fit.below_floor, static_cast<int>(at_floor.size()));
  // Without the floor the plateau is all the fit sees from the smallest step: no order.
  const OrderFit blind = fit_order(no_floor);
  EXPECT_FALSE(blind.slope.has_value());
  EXPECT_EQ(blind.reason.rfind("not converging", 0), 0u) << blind.reason;
}

TEST(FitOrder, NoOrderFromFewerThanThreePoints) {
  EXPECT_FALSE(fit_order({{0.1, 1e-3}}).slope.has_value());
  EXPECT_FALSE(fit_order({{0.1, 1e-3, 0.0}, {0.05, 1e-4, 1e-3}}).slope.has_value());
  EXPECT_FALSE(fit_order({{0.1, NAN}, {0.05, 1e-4}}).slope.has_value());
  const OrderFit two = fit_order({{0.1, 1e-2}, {0.05, 5e-3}, {0.025, NAN}});
  EXPECT_FALSE(two.slope.has_value());
  EXPECT_EQ(two.reason,
            "too few points: 2 in a row between the rounding floor and saturation, "
            "three needed (1 failed)");
}

// ODE, Box2D and the soft body on spring_pair: their springs lose the swing, and the error
// sits at its amplitude (0.05 m) whatever the step. The fit used to call that order 0.11.
TEST(FitOrder, ErrorsSaturatedAtTheMotionsScaleGiveNoOrder) {
  const OrderFit fit = fit_order(sweep({0.05, 0.05, 0.05, 0.049, 0.044, 0.032}), 0.01);
  EXPECT_FALSE(fit.slope.has_value());
  EXPECT_EQ(fit.saturated, 6);
  EXPECT_EQ(fit.reason,
            "saturated: every error is at or above a tenth of the motion's scale "
            "(0.01 m)");
  EXPECT_EQ(fit.local_slopes.size(), 5u);
}

// Explicit Euler on spring_pair: three runs beside "diverged", each error several times the
// one below it as the step nears the limit. The fit used to call that order 2.54.
TEST(FitOrder, ErrorsBesideADivergenceAreNotAsymptotic) {
  const OrderFit fit = fit_order(sweep({NAN, NAN, NAN, 3.1, 0.35, 0.092}));
  EXPECT_FALSE(fit.slope.has_value());
  EXPECT_EQ(fit.failed, 3);
  EXPECT_EQ(fit.reason.rfind("not asymptotic", 0), 0u) << fit.reason;
}

// RK4 on tiny_mass_fall: slopes 4.03 and 4.37 from the smallest steps, then 15.6 towards the
// stability limit. Only the first three points are in the asymptotic range (it was 7.64).
TEST(FitOrder, OnlyTheStepsWhoseLocalSlopesAgreeAreFitted) {
  const OrderFit fit = fit_order(sweep({NAN, NAN, NAN, NAN, 0.0077, 1.6e-7, 7.5e-9, 4.6e-10}));
  ASSERT_TRUE(fit.slope.has_value()) << fit.reason;
  EXPECT_NEAR(*fit.slope, 4.2, 0.1);
  EXPECT_EQ(fit.used, 3);
  ASSERT_EQ(fit.local_slopes.size(), 3u);
  EXPECT_TRUE(fit.local_slopes[0].in_fit && fit.local_slopes[1].in_fit);
  EXPECT_FALSE(fit.local_slopes[2].in_fit);
  EXPECT_NEAR(fit.local_slopes[2].slope, 15.6, 0.1);
}

// Semi-implicit Euler on spring_pair: local slopes 1.19 then 1.32, then 1.48 and 1.68 as the
// step grows: a drift from about 1.7 down towards 1, not an order of 1.26. Two slopes that
// differ by more than a tenth of their size give no order; two that agree still do.
TEST(FitOrder, TwoLocalSlopesThatDriftApartGiveNoOrder) {
  std::vector<ErrorPoint> drifting;
  double error = 1e-6, dt = 1.0 / 960;
  for (double slope : {1.19, 1.32, 1.48, 1.68}) {
    drifting.insert(drifting.begin(), {dt, error, 0.0});
    error *= std::pow(2.0, slope), dt *= 2;
  }
  drifting.insert(drifting.begin(), {dt, error, 0.0});
  const OrderFit fit = fit_order(drifting, 1.1e-6 * std::pow(2.0, 1.19 + 1.32 + 0.01));
  EXPECT_FALSE(fit.slope.has_value());
  EXPECT_EQ(fit.reason.rfind("not asymptotic: only two local slopes in range, 1.19 then 1.32", 0),
            0u)
      << fit.reason;
  // 4.03 then 4.37 agree to a tenth of 4.2 (RK4 on tiny_mass_fall).
  const OrderFit agreeing = fit_order(sweep({0.0077, 1.6e-7, 7.5e-9, 4.6e-10}), 1e-3);
  EXPECT_TRUE(agreeing.slope.has_value()) << agreeing.reason;
}

// Float engines on push: the error grows as the step shrinks. The fit used to call it -1.06.
TEST(FitOrder, AnErrorThatGrowsAsDtShrinksIsRounding) {
  const OrderFit fit = fit_order(sweep({8.1e-7, 2e-6, 4.3e-6, 2e-5, 1.3e-5, 3.4e-5}));
  EXPECT_FALSE(fit.slope.has_value());
  EXPECT_EQ(fit.reason.rfind("rounding: the error grows as dt shrinks", 0), 0u) << fit.reason;
}

// Rounding piles up step by step: a run of a million steps has a floor ten thousand times
// higher than a run of a hundred, so its rounding noise cannot pass as truncation error; a
// float engine's floor is float's epsilon.
TEST(ErrorFloor, GrowsWithTheNumberOfStepsAndThePrecision) {
  Trajectory reference;
  reference.states = {{BodyState{{0.0, 1000.0, 0.0}, {}, {}, {}}}};
  const double eps = std::numeric_limits<double>::epsilon();
  EXPECT_DOUBLE_EQ(error_floor(largest_position(reference), 0.0, 10), 100 * eps * 1000.0);
  EXPECT_DOUBLE_EQ(error_floor(largest_position(reference), 0.0, 1000000), 1e6 * eps * 1000.0);
  EXPECT_DOUBLE_EQ(error_floor(largest_position(reference), 1e-9, 10), 1e-8);
  const double float_eps = std::numeric_limits<float>::epsilon();
  EXPECT_DOUBLE_EQ(error_floor(1000.0, 0.0, 10, float_eps), 100 * float_eps * 1000.0);
}

TEST(Travel, IsTheLargestDistanceFromTheStart) {
  Trajectory t;
  t.states = {{BodyState{{5.0, 0.0, 0.0}, {}, {}, {}}},
              {BodyState{{5.0, 0.3, 0.0}, {}, {}, {}}},
              {BodyState{{5.0, -0.4, 0.0}, {}, {}, {}}}};
  EXPECT_DOUBLE_EQ(largest_travel(t), 0.4);
  EXPECT_DOUBLE_EQ(largest_position(t), std::hypot(5.0, 0.4));
}

}  // namespace
}  // namespace bb
