// What a scene uses and what a backend can simulate, as a small set of flags.
#pragma once

#include <bitset>
#include <string>
#include <vector>

namespace bb {

enum class Feature {
  ThreeD,         ///< motion outside the x-y plane (dims = 3)
  Gravity,        ///< non-zero gravity
  Drag,           ///< quadratic air drag on some body
  Magnus,         ///< spin lift F = k (omega x (v - wind)) on some body
  Wind,           ///< non-zero wind that drag or Magnus sees
  GroundContact,  ///< a ground plane
  BodyContact,    ///< bodies that touch each other
  Restitution,    ///< bouncy contacts
  Friction,       ///< contacts with friction
  Springs,        ///< springs between bodies
  Hinge,          ///< a body turning about a fixed axis
  Rotation,       ///< a body that spins (non-zero angular velocity)
  Boxes,          ///< box-shaped bodies
  Impulse,        ///< instantaneous pushes at given times
  AppliedForce,   ///< a constant force or torque on some body
  Sailing,        ///< a boat's sail in the wind, its hull in the water
  Waves,          ///< a kinematic wave surface: positions from a formula, nothing integrated
  Count
};

class FeatureSet {
 public:
  FeatureSet() = default;
  FeatureSet(std::initializer_list<Feature> features) {
    for (Feature f : features) add(f);
  }
  void add(Feature f) { bits_.set(static_cast<std::size_t>(f)); }
  bool has(Feature f) const { return bits_.test(static_cast<std::size_t>(f)); }
  /// Features in `this` that `other` lacks.
  std::vector<Feature> missing_from(const FeatureSet& other) const;
  bool operator==(const FeatureSet&) const = default;
  /// Every feature of either set.
  FeatureSet operator|(const FeatureSet& other) const {
    FeatureSet out = *this;
    out.bits_ |= other.bits_;
    return out;
  }

 private:
  std::bitset<static_cast<std::size_t>(Feature::Count)> bits_;
};

/// Short lower-case name, e.g. "ground-contact".
std::string feature_name(Feature f);

/// What a backend without `f` is told beyond its name, or "": a kinematic wave surface is
/// moved by its formula and has nothing for an integrator to do.
std::string feature_absence_note(Feature f);
/// What a backend simulates by taking the force model's loads before each step
/// (physics/step_start.hpp): gravity and every force term.
inline FeatureSet force_stage_features() {
  return {Feature::Gravity, Feature::Drag,         Feature::Magnus,
          Feature::Wind,    Feature::AppliedForce, Feature::Sailing};
}

/// Every feature in order, for listings.
std::vector<Feature> all_features();

}  // namespace bb
