// A map (two [[sweep]]s) split into shards, each point a unit of its own, and merged is the
// map unsplit, byte for byte: its results, its page and its pictures (`run --shard I/N`).
#include <gtest/gtest.h>

#include <filesystem>

#include "support/program.hpp"
#include "support/spring_pair_case.hpp"
#include "support/test_support.hpp"

namespace bb {
namespace {

/// Two unit masses on a spring, a map of its stiffness by the step.
const std::string kSpringMap =
    test::spring_pair_case("spring_map", "0.1", "[0.1, 0.05]", "0.05") + R"([course]
integrators = ["explicit-euler", "semi-implicit-euler"]
[[observe]]
kind = "max_stretch"
[[sweep]]
parameter = "spring.1.stiffness"
values = [40.0, 300.0, 900.0]
onset = "max_stretch"
onset_above = 2.0
[[sweep]]
parameter = "dt"
values = [0.1, 0.05, 0.02]
)";

TEST(MapShards, AMapsShardsMergedAreTheMapUnsplit) {
  const std::string dir = test::fresh_dir("map_shards");
  const std::string cases = test::write_case(dir, "spring_map.toml", kSpringMap);
  const std::string selection =
      " --no-cost --backends course/explicit-euler,course/semi-implicit-euler";
  for (int i = 1; i <= 3; ++i) {
    const test::Outcome o =
        test::beachball("run " + cases + selection + " --shard " + std::to_string(i) + "/3 --out " +
                        dir + "/shard" + std::to_string(i));
    ASSERT_EQ(o.exit_code, 0) << o.out;
  }
  const test::Outcome merged =
      test::beachball("merge " + dir + "/shard2 " + dir + "/shard3 " + dir + "/shard1 --cases " +
                      cases + " --out " + dir + "/merged");
  ASSERT_EQ(merged.exit_code, 0) << merged.out;
  const test::Outcome whole =
      test::beachball("run " + cases + selection + " --out " + dir + "/whole");
  ASSERT_EQ(whole.exit_code, 0) << whole.out;
  const auto a = test::snapshot(dir + "/merged"), b = test::snapshot(dir + "/whole");
  ASSERT_TRUE(b.count("spring_map.json") && b.count("spring_map-map.svg") &&
              b.count("spring_map-map-course-semi-implicit-euler.svg"))
      << whole.out;
  EXPECT_EQ(a, b);
}

}  // namespace
}  // namespace bb
