// The [grid] generator builds the lattices of "Sproing" with the right springs.
#include <gtest/gtest.h>

#include "study/case_error.hpp"
#include "support/test_support.hpp"

namespace bb {
namespace {

Scene grid_scene(int dims, const std::string& size, int neighbours, const std::string& extra = "") {
  return test::scene_from("name = \"g\"\ndims = " + std::to_string(dims) +
                          "\nduration = 1.0\nsample = 0.1\ndt = [0.1]\n[grid]\nsize = " + size +
                          "\nneighbours = " + std::to_string(neighbours) + "\n" + extra);
}

TEST(Grid, SpringCountsFollowTheNeighbourhood) {
  // 3 x 3 in 2D: 12 axis springs, 4 per diagonal direction.
  EXPECT_EQ(grid_scene(2, "[3, 3]", 4).springs.size(), 12u);
  EXPECT_EQ(grid_scene(2, "[3, 3]", 6).springs.size(), 16u);
  EXPECT_EQ(grid_scene(2, "[3, 3]", 8).springs.size(), 20u);
  // 2 x 2 x 2 in 3D: 12 edges, 12 face diagonals, 4 body diagonals.
  EXPECT_EQ(grid_scene(3, "[2, 2, 2]", 6).springs.size(), 12u);
  EXPECT_EQ(grid_scene(3, "[2, 2, 2]", 18).springs.size(), 24u);
  EXPECT_EQ(grid_scene(3, "[2, 2, 2]", 26).springs.size(), 28u);
}

TEST(Grid, RestLengthsAreLatticeDistancesAndJitterIsRepeatable) {
  const Scene a = grid_scene(2, "[4, 4]", 8, "spacing = 0.5\njitter = 0.01\nseed = 3\n");
  const Scene b = grid_scene(2, "[4, 4]", 8, "spacing = 0.5\njitter = 0.01\nseed = 3\n");
  const Scene c = grid_scene(2, "[4, 4]", 8, "spacing = 0.5\njitter = 0.01\nseed = 4\n");
  for (const Spring& s : a.springs) {
    const bool axis = std::abs(s.rest_length - 0.5) < 1e-12;
    const bool diagonal = std::abs(s.rest_length - 0.5 * std::sqrt(2.0)) < 1e-12;
    EXPECT_TRUE(axis || diagonal) << s.rest_length;
  }
  bool moved = false, differs = false;
  for (std::size_t i = 0; i < a.bodies.size(); ++i) {
    EXPECT_EQ(a.bodies[i].position, b.bodies[i].position);
    const Vec3 lattice{(i % 4) * 0.5, -double(i / 4) * 0.5, 0.0};
    EXPECT_LE(std::abs(a.bodies[i].position.x() - lattice.x()), 0.01);
    EXPECT_EQ(a.bodies[i].position.z(), 0.0);  // 2D jitter stays in the plane
    moved = moved || !(a.bodies[i].position == lattice);
    differs = differs || !(a.bodies[i].position == c.bodies[i].position);
  }
  EXPECT_TRUE(moved);
  EXPECT_TRUE(differs);
}

TEST(Grid, AnchoredTopRowIsFixedAndHasNoSpringsAmongItself) {
  const Scene s = grid_scene(2, "[3, 2]", 4, "anchored = \"top-row\"\n");
  for (const Body& b : s.bodies) EXPECT_EQ(b.fixed, b.name.ends_with("_0")) << b.name;
  // 7 lattice springs, minus the 2 that join two anchored particles.
  EXPECT_EQ(s.springs.size(), 5u);
}

TEST(Grid, RowsUpStartTheSheetAboveItsAnchoredRow) {
  // The seed's "Sproing Cloth" starts raised above the anchored row and falls from it.
  const Scene s = grid_scene(2, "[2, 3]", 4,
                             "anchored = \"top-row\"\nrows = \"up\"\norigin = [0.0, 5.0, 0.0]\n");
  const Body& anchored = s.bodies[s.body_index("p0_0")];
  const Body& highest = s.bodies[s.body_index("p0_2")];
  EXPECT_TRUE(anchored.fixed);
  EXPECT_FALSE(highest.fixed);
  EXPECT_EQ(anchored.position.y(), 5.0);
  EXPECT_EQ(highest.position.y(), 7.0);
  EXPECT_THROW(grid_scene(2, "[2, 3]", 4, "rows = \"sideways\"\n"), CaseError);
}

}  // namespace
}  // namespace bb
