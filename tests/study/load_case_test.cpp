// The whole case format loads into the scene model, and the bundled suite is valid.
#include "study/load_case.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "model/contact_pairs.hpp"
#include "seam/engine_keys.hpp"
#include "study/backend_names.hpp"
#include "study/case_error.hpp"
#include "support/engine_support.hpp"
#include "support/test_support.hpp"

namespace bb {
namespace {

TEST(LoadCase, EveryKeyOfTheFormatLoads) {
  const Scene s = load_case(test::source_path("tests/cases/every_key.toml"));
  EXPECT_EQ(s.name, "every_key");
  EXPECT_EQ(s.seed, "7. Springs");
  ASSERT_TRUE(s.air.has_value());
  EXPECT_DOUBLE_EQ(s.air->wind.x(), 1.0);
  ASSERT_TRUE(s.ground.has_value());
  EXPECT_DOUBLE_EQ(s.ground->normal.y(), 1.0);  // normalised
  EXPECT_DOUBLE_EQ(s.ground->friction_kinetic, 0.5);
  // Three bodies plus a 3 x 2 grid of particles.
  ASSERT_EQ(s.bodies.size(), 3u + 6u);
  const Body& a = s.bodies[0];
  EXPECT_TRUE(a.shell);
  EXPECT_NEAR(angle_about_z(a.orientation), M_PI / 2.0, 1e-12);
  EXPECT_EQ(s.bodies[1].shape, Shape::Point);
  EXPECT_EQ(s.bodies[2].shape, Shape::Box);
  EXPECT_EQ(s.body_index("p2_1"), 3 + 5);
  EXPECT_TRUE(s.bodies[s.body_index("p0_0")].fixed);  // top row anchored
  EXPECT_FALSE(s.bodies[s.body_index("p0_1")].fixed);
  ASSERT_EQ(s.contacts.size(), 2u);
  EXPECT_TRUE(s.contacts[1].all_pairs);
  // The case's own springs follow the grid's; rest length defaults to the initial distance.
  ASSERT_GE(s.springs.size(), 2u);
  const Spring& ab = s.springs[s.springs.size() - 2];
  EXPECT_EQ(ab.body_a, 0);
  EXPECT_EQ(ab.body_b, 1);
  EXPECT_DOUBLE_EQ(ab.rest_length, 2.0);
  EXPECT_DOUBLE_EQ(s.springs.back().rest_length, 1.5);
  ASSERT_EQ(s.hinges.size(), 1u);
  EXPECT_EQ(s.hinges[0].body, 2);
  EXPECT_EQ(engine_setting(s.engines, *test::description_of("bullet"), "solver_iterations"), 20.0);
  EXPECT_EQ(engine_setting(s.engines, *test::description_of("ode"), "quick_step"), 1.0);
  EXPECT_EQ(engine_setting(s.engines, *test::description_of("ode"), "quick_step_iterations"),
            20.0);  // default
  ASSERT_EQ(s.observes.size(), 5u);
  EXPECT_EQ(s.observes[0].name, "bounce_apex/a/2");
  EXPECT_FALSE(s.observes[1].rest_speed);
  EXPECT_EQ(s.observes[2].rest_speed, 0.001);
  EXPECT_EQ(s.observes[3].axis, Vec3(0.0, 0.0, -1.0));
  EXPECT_EQ(s.observes[4].level, 0.5);
  EXPECT_FALSE(s.observes[3].level);
  ASSERT_EQ(s.gates.size(), 1u);
  EXPECT_EQ(s.gates[0].backend, "course/rk4+mirror");
  // Claims: the text's words and how each side is read; the case's own, and what a
  // divergence counts as.
  ASSERT_EQ(s.claims.size(), 2u);
  EXPECT_EQ(s.claims[0].quote, "This makes it much better");
  EXPECT_FALSE(s.claims[0].own);
  EXPECT_TRUE(s.claims[0].against_reference);
  EXPECT_EQ(s.claims[0].diverged, DivergedCounts::Nothing);
  EXPECT_TRUE(s.claims[1].own);
  EXPECT_EQ(s.claims[1].quote, "");
  EXPECT_FALSE(s.claims[1].against_reference);
  EXPECT_EQ(s.claims[1].diverged, DivergedCounts::Fails);
}

TEST(LoadCase, CourseVariantsAreNamedOnlyByWhatVaries) {
  const Scene s = load_case(test::source_path("tests/cases/every_key.toml"));
  std::vector<std::string> names;
  for (const CourseVariant& v : course_variants(s)) names.push_back(v.name);
  EXPECT_EQ(names, (std::vector<std::string>{"course/explicit-euler+reflect",
                                             "course/explicit-euler+mirror", "course/rk4+reflect",
                                             "course/rk4+mirror"}));
}

TEST(LoadCase, DefaultsWhenOptionalKeysAreOmitted) {
  const Scene s = test::scene_from(test::kMinimalCase);
  EXPECT_EQ(s.title, "minimal");
  EXPECT_DOUBLE_EQ(s.gravity.y(), -9.81);
  EXPECT_EQ(s.course.integrators.size(), 4u);
  EXPECT_EQ(s.sample_count(), 10);
  EXPECT_EQ(s.steps_per_sample(0.05), 2);
  // The sweep is sorted from the largest step down.
  EXPECT_DOUBLE_EQ(s.dt.front(), 0.1);
  EXPECT_DOUBLE_EQ(s.report_dt, 0.05);
}

TEST(LoadCase, EveryBundledCaseLoads) {
  int count = 0;
  for (const auto& entry : std::filesystem::directory_iterator(test::source_path("cases"))) {
    if (entry.path().extension() != ".toml") continue;
    const Scene s = load_case(entry.path().string());
    EXPECT_EQ(s.name + ".toml", entry.path().filename().string());
    ++count;
    // A kinematic wave surface has no step to sweep and no error to gate: its formula is
    // its answer (its claims check it).
    if (s.waves) {
      EXPECT_FALSE(s.claims.empty()) << s.name;
      continue;
    }
    // The issue asks for at least five halvings from 1/30 s.
    ASSERT_GE(s.dt.size(), 6u) << s.name;
    EXPECT_NEAR(s.dt.front(), 1.0 / 30.0, 1e-15) << s.name;
    for (std::size_t i = 1; i < s.dt.size(); ++i) EXPECT_NEAR(s.dt[i - 1] / s.dt[i], 2.0, 1e-12);
    EXPECT_FALSE(s.gates.empty()) << s.name;
  }
  EXPECT_GE(count, 3);
}

// The limits' edges: 64-character names, tabs and CRLF line ends in the file, and
// non-ASCII text and markup in a title load.
TEST(LoadCase, NamesOfSixtyFourCharactersTabsAndLineEndsLoad) {
  std::string text = test::kMinimalCase;
  text.replace(text.find("\"minimal\""), 9, "\"" + std::string(64, 'c') + "\"");
  text.replace(text.find("\"ball\""), 6, "\"" + std::string(64, 'B') + "\"");
  text = "title = \"An éléphant | <b>\"\t# a comment\t\n" + text;
  std::string crlf;
  for (char c : text) crlf += c == '\n' ? std::string("\r\n") : std::string(1, c);
  const Scene s = test::scene_from(crlf);
  EXPECT_EQ(s.name, std::string(64, 'c'));
  EXPECT_EQ(s.bodies.at(0).name, std::string(64, 'B'));
  EXPECT_EQ(s.title, "An éléphant | <b>");
  // A tab written as an escape is a control character in the value; a raw tab in the
  // file, outside strings, is whitespace.
  EXPECT_THROW(test::scene_from("title = \"a\\tb\"\n" + std::string(test::kMinimalCase)),
               CaseError);
}

// ["<body>", "ground"] gives that body's contact with the ground its own values; the
// others keep the [ground]'s, and no body-to-body contact appears.
TEST(LoadCase, AContactWithTheGroundSetsThatBodysPairOnly) {
  const Scene scene = test::scene_from(test::level_ground_case("floor", "friction_static = 0.2\n") +
                                       test::resting_box("ice", 0.0) +
                                       test::resting_box("rubber", 5.0) + R"([[contact]]
bodies = ["ground", "rubber"]
friction_static = 1.0
friction_kinetic = 0.8
)");
  const std::vector<ContactPair> pairs = contact_pairs(scene);
  ASSERT_EQ(pairs.size(), 2u);
  EXPECT_EQ(ground_pair(scene, 0)->friction_static, 0.2);
  EXPECT_EQ(ground_pair(scene, 0)->friction_kinetic, 0.2);
  EXPECT_EQ(ground_pair(scene, 1)->friction_static, 1.0);
  EXPECT_EQ(ground_pair(scene, 1)->friction_kinetic, 0.8);
  EXPECT_TRUE(scene.features().has(Feature::Friction));
  EXPECT_FALSE(scene.features().has(Feature::BodyContact));
}

// The model's loader knows no observable kind of its own: it takes the words it is handed.
TEST(LoadCase, TakesTheObservableKindsItIsHanded) {
  const std::string text =
      "name = \"v\"\ndims = 2\nduration = 1.0\nsample = 0.5\ndt = [0.5]\n"
      "[[body]]\nname = \"b\"\nshape = \"sphere\"\nradius = 0.1\nmass = 1.0\n"
      "[[observe]]\nkind = \"wobble\"\nn = 2\n";
  CaseVocabulary counted_scene_wide;
  counted_scene_wide.observables.push_back({"wobble", true, true});
  const Scene scene = parse_case(text, "v.toml", counted_scene_wide);
  ASSERT_EQ(scene.observes.size(), 1u);
  EXPECT_EQ(scene.observes[0].name, "wobble/2");
  try {
    parse_case(text, "v.toml", CaseVocabulary{});
    FAIL() << "a kind outside the vocabulary loaded";
  } catch (const CaseError& e) {
    EXPECT_NE(std::string(e.what()).find("unknown observable kind 'wobble'"), std::string::npos)
        << e.what();
  }
}

// Nor any engine: the catalogue is handed to it, and a table of an engine it was not handed
// is refused.
TEST(LoadCase, TakesTheEnginesItIsHanded) {
  const std::string text =
      "name = \"v\"\ndims = 2\nduration = 1.0\nsample = 0.5\ndt = [0.5]\n"
      "[[body]]\nname = \"b\"\nshape = \"sphere\"\nradius = 0.1\nmass = 1.0\n"
      "[engines.ode]\nerp = 0.1\n";
  const Scene scene = parse_case(text, "v.toml", every_word());
  EXPECT_EQ(engine_setting(scene.engines, *test::description_of("ode"), "erp"), 0.1);
  CaseVocabulary no_engines = every_word();
  no_engines.engines.clear();
  EXPECT_THROW(parse_case(text, "v.toml", no_engines), CaseError);
}

}  // namespace
}  // namespace bb
