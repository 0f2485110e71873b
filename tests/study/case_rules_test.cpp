// Case text that could mean two things means one: a pair named by itself wins over ["*"]
// whatever the order; backends a case names are backends that can run it; vectors keep to
// their ranges. (Each refusal also has a file in tests/bad_cases/.)
#include <gtest/gtest.h>

#include "model/contact_pairs.hpp"
#include "run/engine_catalogue.hpp"
#include "study/backend_names.hpp"
#include "study/case_error.hpp"
#include "study/vector_limits.hpp"
#include "support/test_support.hpp"

namespace bb {
namespace {

std::string three_balls(const std::string& contacts) {
  std::string text = "name = \"c\"\ndims = 2\nduration = 1.0\nsample = 0.1\ndt = [0.1]\n";
  for (const char* name : {"a", "b", "c"})
    text += std::string("[[body]]\nname = \"") + name +
            "\"\nradius = 0.5\nmass = 1.0\nposition = [" + std::to_string(3 * (name[0] - 'a')) +
            ", 1.0, 0.0]\n";
  return text + contacts;
}

double restitution_between(const Scene& s, int a, int b) {
  for (const ContactPair& p : contact_pairs(s))
    if ((p.a == a && p.b == b) || (p.a == b && p.b == a)) return p.restitution;
  ADD_FAILURE() << "no pair " << a << ", " << b;
  return -1.0;
}

TEST(CaseRules, APairNamedByItselfWinsOverStarWhateverTheOrder) {
  const std::string star = "[[contact]]\nbodies = [\"*\"]\nrestitution = 1.0\n";
  const std::string ab = "[[contact]]\nbodies = [\"b\", \"a\"]\nrestitution = 0.0\n";
  for (const std::string& contacts : {star + ab, ab + star}) {
    const Scene s = test::scene_from(three_balls(contacts));
    EXPECT_EQ(restitution_between(s, 0, 1), 0.0) << contacts;
    EXPECT_EQ(restitution_between(s, 0, 2), 1.0) << contacts;
    EXPECT_EQ(restitution_between(s, 1, 2), 1.0) << contacts;
    EXPECT_EQ(contact_pairs(s).size(), 3u);
  }
}

TEST(CaseRules, TheBackendsACaseRunsExistAndCanRunIt) {
  const auto has = [](const std::vector<std::string>& v, const std::string& s) {
    return std::find(v.begin(), v.end(), s) != v.end();
  };
  std::string three_d = test::kMinimalCase;
  three_d.replace(three_d.find("dims = 2"), 8, "dims = 3");
  const std::vector<std::string> flat =
      runnable_backend_names(test::scene_from(test::kMinimalCase), engine_catalogue());
  const std::vector<std::string> deep =
      runnable_backend_names(test::scene_from(three_d), engine_catalogue());
  for (const auto& names : {flat, deep}) {
    EXPECT_TRUE(has(names, "mujoco"));  // free bodies: it runs the minimal case
    // Springs by hand are their engine itself on a scene without springs.
    EXPECT_FALSE(has(names, "ode/force"));
    EXPECT_FALSE(has(names, "box2d/force"));
    EXPECT_TRUE(has(names, "reference"));
    EXPECT_TRUE(has(names, "ode"));
    EXPECT_TRUE(has(names, "bullet"));
  }
  EXPECT_TRUE(has(flat, "box2d"));
  EXPECT_FALSE(has(deep, "box2d"));
  EXPECT_NE(
      why_backend_cannot_run(test::scene_from(three_d), "box2d", engine_catalogue()).find("3d"),
      std::string::npos);
  // The load message that lists them lists only those.
  try {
    test::scene_from(std::string(test::kMinimalCase) +
                     "[[gate]]\nbackend = \"physx\"\nmetric = \"position_max\"\nmax = 1.0\n");
    FAIL() << "a gate on an unknown backend loaded";
  } catch (const CaseError& e) {
    EXPECT_NE(e.problem().find("it runs: reference, course/"), std::string::npos) << e.problem();
    EXPECT_EQ(e.problem().find("/force"), std::string::npos) << e.problem();
  }
}

TEST(CaseRules, EveryVectorKindRefusesANormBeyondItsRangeAndTakesOneWithin) {
  for (VectorKind kind : {VectorKind::Position, VectorKind::Velocity, VectorKind::AngularVelocity,
                          VectorKind::Direction, VectorKind::Gravity, VectorKind::Wind,
                          VectorKind::Force, VectorKind::Impulse}) {
    const VectorLimit& limit = vector_limit(kind);
    EXPECT_EQ(vector_limit_problem(kind, {0.0, limit.most, 0.0}), "");
    EXPECT_NE(vector_limit_problem(kind, {0.0, limit.most * 1.001, 0.0}), "");
    // Huge components that overflow when squared are measured, not turned to infinity.
    const std::string huge = vector_limit_problem(kind, {0.0, 1e160, 1e160});
    EXPECT_NE(huge.find("1.41421e+160"), std::string::npos) << huge;
  }
  EXPECT_NE(vector_limit_problem(VectorKind::Direction, {0.0, 1e-10, 0.0}), "");
  EXPECT_EQ(vector_limit_problem(VectorKind::Velocity, {0.0, 0.0, 0.0}), "");
}

TEST(CaseRules, EqualFrictionCoefficientsAreFineAndKineticAboveStaticIsNot) {
  const std::string ground = std::string(test::kMinimalCase) + "[ground]\nfriction_static = 0.5\n";
  EXPECT_NO_THROW(test::scene_from(ground + "friction_kinetic = 0.5\n"));
  EXPECT_NO_THROW(test::scene_from(ground + "friction_kinetic = 0.3\n"));
  EXPECT_THROW(test::scene_from(ground + "friction_kinetic = 0.5000001\n"), CaseError);
}

// One coefficient alone sets both, in [ground] and in a [[contact]]: a static coefficient
// left at 0 beside a kinetic one pushed a stopped block up a slope in the reference.
TEST(CaseRules, OneFrictionCoefficientAloneSetsBoth) {
  const Scene kinetic =
      test::scene_from(std::string(test::kMinimalCase) + "[ground]\nfriction_kinetic = 0.4\n");
  EXPECT_EQ(kinetic.ground->friction_static, 0.4);
  EXPECT_EQ(kinetic.ground->friction_kinetic, 0.4);
  const Scene fixed = test::scene_from(std::string(test::kMinimalCase) +
                                       "[ground]\nfriction_static = 0.7\n"
                                       "[[contact]]\nbodies = [\"ball\", \"ground\"]\n"
                                       "friction_kinetic = 0.3\n");
  ASSERT_EQ(fixed.contacts.size(), 1u);
  EXPECT_EQ(fixed.contacts[0].friction_static, 0.3);
  EXPECT_EQ(fixed.contacts[0].friction_kinetic, 0.3);
}

}  // namespace
}  // namespace bb
