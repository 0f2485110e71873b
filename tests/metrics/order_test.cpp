// The order fit recovers exact slopes, leaves out points at their error floor and counts
// them, and the floor grows with the number of steps a run takes.
#include "metrics/order.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace bb {
namespace {

TEST(FitOrder, ExactOnSyntheticPowerLaws) {
  for (double p : {1.0, 2.0, 4.0, 0.5}) {
    std::vector<ErrorPoint> points;
    for (double dt = 1.0 / 30; dt > 1e-3; dt /= 2) points.push_back({dt, 3.7 * std::pow(dt, p)});
    const OrderFit fit = fit_order(points);
    ASSERT_TRUE(fit.slope.has_value());
    EXPECT_NEAR(*fit.slope, p, 1e-12);
    EXPECT_EQ(fit.used, static_cast<int>(points.size()));
    EXPECT_EQ(fit.below_floor, 0);
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
  EXPECT_LT(*fit_order(no_floor).slope, 3.5);  // with the floor included the slope is wrong
}

TEST(FitOrder, NoOrderFromFewerThanTwoPoints) {
  EXPECT_FALSE(fit_order({{0.1, 1e-3}}).slope.has_value());
  EXPECT_FALSE(fit_order({{0.1, 1e-3, 0.0}, {0.05, 1e-4, 1e-3}}).slope.has_value());
  EXPECT_FALSE(fit_order({{0.1, NAN}, {0.05, 1e-4}}).slope.has_value());
}

// Rounding piles up step by step: a run of a million steps has a floor ten thousand times
// higher than a run of a hundred, so its rounding noise cannot pass as truncation error.
TEST(ErrorFloor, GrowsWithTheNumberOfSteps) {
  Trajectory reference;
  reference.states = {{BodyState{{0.0, 1000.0, 0.0}, {}, {}, {}}}};
  const double eps = std::numeric_limits<double>::epsilon();
  EXPECT_DOUBLE_EQ(error_floor(largest_position(reference), 0.0, 10), 100 * eps * 1000.0);
  EXPECT_DOUBLE_EQ(error_floor(largest_position(reference), 0.0, 1000000), 1e6 * eps * 1000.0);
  EXPECT_DOUBLE_EQ(error_floor(largest_position(reference), 1e-9, 10), 1e-8);
}

}  // namespace
}  // namespace bb
