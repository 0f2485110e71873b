#include "model/features.hpp"

namespace bb {

std::vector<Feature> FeatureSet::missing_from(const FeatureSet& other) const {
  std::vector<Feature> out;
  for (Feature f : all_features())
    if (has(f) && !other.has(f)) out.push_back(f);
  return out;
}

std::string feature_name(Feature f) {
  switch (f) {
    case Feature::ThreeD:
      return "3d";
    case Feature::Gravity:
      return "gravity";
    case Feature::Drag:
      return "drag";
    case Feature::Magnus:
      return "magnus";
    case Feature::Wind:
      return "wind";
    case Feature::GroundContact:
      return "ground-contact";
    case Feature::BodyContact:
      return "body-contact";
    case Feature::Restitution:
      return "restitution";
    case Feature::Friction:
      return "friction";
    case Feature::Springs:
      return "springs";
    case Feature::Hinge:
      return "hinge";
    case Feature::Impulse:
      return "impulse";
    case Feature::AppliedForce:
      return "applied-force";
    case Feature::Sailing:
      return "sailing";
    case Feature::Waves:
      return "waves";
    case Feature::Rotation:
      return "rotation";
    case Feature::Boxes:
      return "boxes";
    case Feature::Count:
      break;
  }
  return "?";
}

std::vector<Feature> all_features() {
  std::vector<Feature> out;
  for (int i = 0; i < static_cast<int>(Feature::Count); ++i) out.push_back(static_cast<Feature>(i));
  return out;
}

std::string feature_absence_note(Feature f) {
  if (f == Feature::Waves)
    return "a kinematic surface, moved by its formula, which the reference evaluates: nothing "
           "to integrate";
  return "";
}

}  // namespace bb
