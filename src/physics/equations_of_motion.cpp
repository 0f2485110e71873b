#include "physics/equations_of_motion.hpp"

namespace bb {

EquationsOfMotion::EquationsOfMotion(const World& scene)
    : forces_(scene), torque_(scene.bodies.size(), Vec3::Zero()) {
  for (const Body& b : scene.bodies) inverse_mass_.push_back(b.fixed ? 0.0 : 1.0 / b.mass);
}

}  // namespace bb
