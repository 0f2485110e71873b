// The order fit recovers exact slopes and ignores points at the reference's floor.
#include "metrics/order.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace bb {
namespace {

TEST(FitOrder, ExactOnSyntheticPowerLaws) {
  for (double p : {1.0, 2.0, 4.0, 0.5}) {
    std::vector<ErrorPoint> points;
    for (double dt = 1.0 / 30; dt > 1e-3; dt /= 2) points.push_back({dt, 3.7 * std::pow(dt, p)});
    const auto order = fit_order(points, 0.0);
    ASSERT_TRUE(order.has_value());
    EXPECT_NEAR(*order, p, 1e-12);
  }
}

TEST(FitOrder, PointsAtOrBelowTheFloorAreLeftOut) {
  // An RK4-like series that flattens at 1e-9 where the reference's own error sits.
  std::vector<ErrorPoint> points;
  for (double dt = 1.0 / 30; dt > 1e-3; dt /= 2)
    points.push_back({dt, std::max(std::pow(dt, 4), 1e-9)});
  EXPECT_NEAR(*fit_order(points, 2e-9), 4.0, 1e-12);
  EXPECT_LT(*fit_order(points, 0.0), 3.5);  // with the floor included the slope is wrong
}

TEST(FitOrder, NoOrderFromFewerThanTwoPoints) {
  EXPECT_FALSE(fit_order({{0.1, 1e-3}}, 0.0).has_value());
  EXPECT_FALSE(fit_order({{0.1, 1e-3}, {0.05, 1e-4}}, 1e-3).has_value());
  EXPECT_FALSE(fit_order({{0.1, NAN}, {0.05, 1e-4}}, 0.0).has_value());
}

}  // namespace
}  // namespace bb
