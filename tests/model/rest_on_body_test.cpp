// rest_on = "<another body>": a body placed on top of another along gravity, touching it
// (overlap 0 to 1e-12 m, from the geometry), its position across gravity kept, a stack placed
// from the bottom whatever the order of the file; and what cannot rest where it is.
#include <gtest/gtest.h>

#include "model/initial_overlap.hpp"
#include "study/case_error.hpp"
#include "support/test_support.hpp"

namespace bb {
namespace {

/// A 2D case (gravity straight down unless `gravity` says otherwise) with every pair
/// touching, and the [[body]] tables `bodies`.
std::string stack(const std::string& bodies, const std::string& gravity = "",
                  const std::string& contact = "[[contact]]\nbodies = [\"*\"]\n") {
  return R"(name = "stack"
dims = )" +
         std::string(gravity.empty() ? "2" : "3") +
         R"(
duration = 0.5
sample = 0.05
dt = [0.05]
)" + gravity +
         bodies + contact;
}

const char* kTable = R"([[body]]
name = "table"
shape = "box"
half_extents = [1.0, 0.2, 0.5]
fixed = true
position = [0.0, 1.0, 0.0]
)";

std::string error_of(const std::string& text) {
  try {
    test::scene_from(text);
  } catch (const CaseError& e) {
    return e.what();
  }
  return "";
}

TEST(RestOnBody, EachShapeTouchesTheOneBelowAndKeepsItsPlaceAcrossGravity) {
  // Listed top first: the stack is placed from the bottom.
  const Scene s = test::scene_from(stack(R"([[body]]
name = "top"
radius = 0.1
mass = 1.0
rest_on = "ball"
position = [0.35, 50.0, 0.0]
[[body]]
name = "ball"
radius = 0.3
mass = 1.0
rest_on = "crate"
position = [0.6, -7.0, 0.0]
[[body]]
name = "crate"
shape = "box"
half_extents = [0.25, 0.15, 0.25]
mass = 1.0
rest_on = "table"
position = [0.5, 0.0, 0.0]
[[body]]
name = "lid"
shape = "box"
half_extents = [0.3, 0.05, 0.3]
mass = 1.0
rest_on = "dome"
position = [-3.1, 0.0, 0.0]
[[body]]
name = "dome"
radius = 0.5
fixed = true
position = [-3.0, 0.5, 0.0]
)" + std::string(kTable)));
  const auto at = [&](const char* name) -> const Body& { return s.bodies[s.body_index(name)]; };
  for (const auto& [upper, lower] : {std::pair<const char*, const char*>{"top", "ball"},
                                     {"ball", "crate"},
                                     {"crate", "table"},
                                     {"lid", "dome"}})
    EXPECT_NEAR(overlap_depth(at(upper), at(lower)), 0.0, 1e-12) << upper << " on " << lower;
  EXPECT_EQ(at("crate").position.x(), 0.5);
  EXPECT_NEAR(at("crate").position.y(), 1.0 + 0.2 + 0.15, 1e-15);
  EXPECT_NEAR(at("ball").position.y(), 1.35 + 0.15 + 0.3, 1e-15);
  EXPECT_EQ(at("lid").position.x(), -3.1);
  EXPECT_NEAR(at("lid").position.y(), 1.0 + 0.05, 1e-15);
  // A sphere off the top of the one below rests on its side, touching.
  EXPECT_EQ(at("top").position.x(), 0.35);
  EXPECT_GT(at("top").position.y(), at("ball").position.y());
}

TEST(RestOnBody, RestsAlongATiltedGravityIn3D) {
  const Scene s = test::scene_from(stack(R"([[body]]
name = "base"
radius = 1.0
fixed = true
[[body]]
name = "crate"
shape = "box"
half_extents = [2.0, 0.1, 2.0]
mass = 1.0
rest_on = "base"
position = [0.1, 5.0, 0.1]
)",
                                         "gravity = [1.0, -9.0, 2.0]\n"));
  const Body& crate = s.bodies[1];
  const Vec3 up = -s.gravity.normalized();
  EXPECT_NEAR(overlap_depth(crate, s.bodies[0]), 0.0, 1e-12);
  EXPECT_NEAR(crate.position.dot(up), 1.1, 1e-12);
  const Vec3 given(0.1, 5.0, 0.1);
  const Vec3 across = given - given.dot(up) * up;
  EXPECT_NEAR((crate.position - crate.position.dot(up) * up - across).norm(), 0.0, 1e-12);
  EXPECT_NEAR((crate.orientation * Vec3::UnitY() - up).norm(), 0.0, 1e-15);
}

TEST(RestOnBody, RefusesWhatCannotRestWhereItIs) {
  const auto resting = [](const std::string& on, const std::string& at) {
    return "[[body]]\nname = \"cup\"\nradius = 0.1\nmass = 1.0\nrest_on = \"" + on +
           "\"\nposition = " + at + "\n";
  };
  EXPECT_NE(error_of(stack(std::string(kTable) + resting("chair", "[0.0, 0.0, 0.0]")))
                .find("\"chair\" is neither \"ground\" nor a body"),
            std::string::npos);
  EXPECT_NE(error_of(stack(std::string(kTable) + resting("table", "[1.5, 0.0, 0.0]")))
                .find("'cup' is not over the top face of box 'table'"),
            std::string::npos);
  EXPECT_NE(error_of(stack(std::string(kTable) + resting("table", "[0.0, 0.0, 0.0]"), "", ""))
                .find("add a [[contact]] with bodies = [\"cup\", \"table\"]"),
            std::string::npos);
  std::string turned = kTable;
  turned.insert(turned.find("fixed"), "angle = 10.0\n");
  EXPECT_NE(error_of(stack(turned + resting("table", "[0.0, 0.0, 0.0]")))
                .find("box 'table' has no face turned up"),
            std::string::npos);
  EXPECT_NE(
      error_of(stack(resting("cup", "[0.0, 0.0, 0.0]"))).find("rests, through rest_on, on itself"),
      std::string::npos);
}

}  // namespace
}  // namespace bb
