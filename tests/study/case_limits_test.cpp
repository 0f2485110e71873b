// Every limit that can be computed from a case's numbers refuses it before anything of the
// case's size is built: the work a refusal does is counted (particles the [grid] generator
// made), never timed.
#include "study/case_limits.hpp"

#include <gtest/gtest.h>

#include "study/case_error.hpp"
#include "support/test_support.hpp"

namespace bb {
namespace {

/// The problem of the CaseError that loading `text` raises, and the particles the [grid]
/// generator made meanwhile.
struct Refusal {
  int line = 0;
  std::string problem;
  long particles_made = 0;
};

Refusal refusal_of(const std::string& text) {
  const long before = grid_particles_made();
  Refusal r;
  try {
    test::scene_from(text);
    ADD_FAILURE() << "loaded without complaint:\n" << text;
  } catch (const CaseError& e) {
    r.line = e.line();
    r.problem = e.problem();
  }
  r.particles_made = grid_particles_made() - before;
  return r;
}

std::string grid_case(int dims, const std::string& timing, const std::string& grid,
                      const std::string& extra = "") {
  return "name = \"big\"\ndims = " + std::to_string(dims) + "\n" + timing + "\n[grid]\n" + grid +
         "\n" + extra;
}

TEST(CaseLimits, TheFuzzersTimeoutIsRefusedBeforeItsGridIsBuilt) {
  const std::string text = test::bytes(
      test::source_path("tests/fuzz_regressions/grid_of_41000_built_before_its_limits.toml"));
  ASSERT_EQ(text.size(), 138u);
  const Refusal r = refusal_of(text);
  EXPECT_EQ(r.line, 5);
  EXPECT_NE(r.problem.find("100 samples of 41000 bodies"), std::string::npos) << r.problem;
  EXPECT_EQ(r.particles_made, 0);
}

// The largest grid the format allows: 46 x 46 x 47 = 99,452 particles (kMaxGridParticles is
// 100,000) with 26 neighbours, about 1.3 million springs. Each limit refuses it in turn, and
// none after building a single particle.
TEST(CaseLimits, TheLargestGridIsRefusedByEachLimitWithoutBuildingIt) {
  const std::string largest = "size = [46, 46, 47]\nneighbours = 26";
  struct Ask {
    std::string timing, extra, problem;
  };
  const std::vector<Ask> asks = {
      // Body-samples: 100 samples of 99,452 bodies.
      {"duration = 100.0\nsample = 1.0\ndt = [1.0]", "", "body-samples a run keeps"},
      // Work: 1000 steps of 1.4 million bodies and springs.
      {"duration = 1.0\nsample = 1.0\ndt = [0.001]", "", "hours of work"},
      // Contact pairs: every pair of 99,452 bodies.
      {"duration = 1.0\nsample = 1.0\ndt = [1.0]", "[[contact]]\nbodies = [\"*\"]\n",
       "contact pairs"},
      // A sweep of 1000 points, each a run of the whole grid.
      {"duration = 1.0\nsample = 1.0\ndt = [1.0]",
       "[[sweep]]\nparameter = \"gravity.y\"\nrange = [-10.0, -9.0, 1000]\n", "[[sweep]] would"},
  };
  for (const Ask& ask : asks) {
    const Refusal r = refusal_of(grid_case(3, ask.timing, largest, ask.extra));
    EXPECT_NE(r.problem.find(ask.problem), std::string::npos) << r.problem;
    EXPECT_EQ(r.particles_made, 0) << ask.problem;
  }
}

TEST(CaseLimits, GridCountsFromNumbersAreTheGridsOwn) {
  struct Shape {
    int dims;
    std::vector<int> size;
    int neighbours;
    bool anchored;
  };
  const std::vector<Shape> shapes = {
      {2, {3, 3}, 4, false},     {2, {5, 2}, 6, true},     {2, {1, 7}, 8, false},
      {2, {4, 4}, 8, true},      {3, {2, 2, 2}, 6, false}, {3, {3, 4, 2}, 18, true},
      {3, {4, 3, 3}, 26, false}, {3, {1, 1, 5}, 26, true}, {3, {5, 1, 3}, 18, false}};
  for (const Shape& s : shapes) {
    std::string size = "[";
    for (std::size_t i = 0; i < s.size.size(); ++i)
      size += (i ? ", " : "") + std::to_string(s.size[i]);
    size += "]";
    const Scene scene = test::scene_from(
        grid_case(s.dims, "duration = 1.0\nsample = 0.1\ndt = [0.1]",
                  "size = " + size + "\nneighbours = " + std::to_string(s.neighbours) +
                      (s.anchored ? "\nanchored = \"top-row\"" : "")));
    const GridCounts counts = grid_counts(s.dims, s.size, s.neighbours, s.anchored);
    EXPECT_EQ(counts.particles, static_cast<double>(scene.bodies.size())) << size;
    EXPECT_EQ(counts.springs, static_cast<double>(scene.springs.size())) << size;
  }
}

TEST(CaseLimits, AllPairsCountEveryPairThatIsNotTwoFixedBodies) {
  CaseSize size;
  size.bodies = 10;
  size.fixed_bodies = 4;
  size.all_pairs = true;
  size.named_pairs = 3;
  // 45 pairs, less the 6 between fixed bodies; pairs named besides ["*"] add nothing.
  EXPECT_EQ(contact_pair_count(size), 39.0);
  size.all_pairs = false;
  EXPECT_EQ(contact_pair_count(size), 3.0);
}

}  // namespace
}  // namespace bb
