// A scene derives the features it uses from what its case file says.
#include <gtest/gtest.h>

#include "support/test_support.hpp"

namespace bb {
namespace {

TEST(Features, DragCaseUsesGravityAndDragOnly) {
  const FeatureSet f = test::scene_from(test::kMinimalCase).features();
  EXPECT_EQ(f, (FeatureSet{Feature::Gravity, Feature::Drag}));
}

TEST(Features, EveryKeyCaseUsesEverything) {
  const FeatureSet f = load_case(test::source_path("tests/cases/every_key.toml")).features();
  for (Feature x :
       {Feature::Gravity, Feature::Drag, Feature::Magnus, Feature::Wind, Feature::GroundContact,
        Feature::BodyContact, Feature::Restitution, Feature::Friction, Feature::Springs,
        Feature::Hinge, Feature::Rotation, Feature::Boxes})
    EXPECT_TRUE(f.has(x)) << feature_name(x);
  EXPECT_FALSE(f.has(Feature::ThreeD));
}

TEST(Features, WindCountsOnlyWhenSomethingFeelsIt) {
  std::string text = test::kMinimalCase;
  text.replace(text.find("density = 1.2"), 13, "density = 1.2\nwind = [3.0, 0.0, 0.0]");
  EXPECT_TRUE(test::scene_from(text).features().has(Feature::Wind));
  text.replace(text.find("drag_coefficient = 0.47"), 23, "drag_coefficient = 0.0");
  EXPECT_FALSE(test::scene_from(text).features().has(Feature::Wind));
  EXPECT_FALSE(test::scene_from(text).features().has(Feature::Drag));
}

TEST(Features, MissingFromNamesWhatIsLacking) {
  const FeatureSet scene{Feature::ThreeD, Feature::Gravity, Feature::Drag};
  const FeatureSet backend{Feature::Gravity, Feature::Drag};
  const auto missing = scene.missing_from(backend);
  ASSERT_EQ(missing.size(), 1u);
  EXPECT_EQ(feature_name(missing[0]), "3d");
}

}  // namespace
}  // namespace bb
