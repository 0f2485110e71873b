// The seed's plank on an axis against the parallel-axis theorem: its formula gives each
// side of the axis the whole plank's mass, so at the centre it is twice the truth, and it
// agrees only with the axis at an end, where one side has no length.
#include "course/plank_inertia.hpp"

#include <gtest/gtest.h>

namespace bb {
namespace {

using course::plank_axis_inertia;
using course::seed_axis_inertia;

TEST(PlankInertia, ParallelAxisEqualsTheTwoSidesWithTheirOwnMass) {
  // Each side as a rod about its end with its share of the mass, m d / l.
  const double m = 2.0, l = 5.0;
  for (double a : {0.0, 0.5, 1.25, 2.0, 2.5}) {
    const double d1 = l / 2 - a, d2 = l / 2 + a;
    const double sides = (m * d1 / l) * d1 * d1 / 3.0 + (m * d2 / l) * d2 * d2 / 3.0;
    EXPECT_NEAR(plank_axis_inertia(m, l, a), sides, 1e-12) << a;
  }
}

TEST(PlankInertia, TheSeedsFormulaIsTwiceTheTruthAtTheCentreAndRightAtAnEnd) {
  const double m = 2.0, l = 5.0;
  EXPECT_NEAR(seed_axis_inertia(m, l, 0.0) / plank_axis_inertia(m, l, 0.0), 2.0, 1e-12);
  EXPECT_NEAR(seed_axis_inertia(m, l, l / 2) / plank_axis_inertia(m, l, l / 2), 1.0, 1e-12);
  // Between, it overestimates, less and less towards the end.
  double previous = 2.0;
  for (double a : {0.5, 1.0, 1.5, 2.0}) {
    const double ratio = seed_axis_inertia(m, l, a) / plank_axis_inertia(m, l, a);
    EXPECT_GT(ratio, 1.0) << a;
    EXPECT_LT(ratio, previous) << a;
    previous = ratio;
  }
}

}  // namespace
}  // namespace bb
