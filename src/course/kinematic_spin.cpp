#include "course/kinematic_spin.hpp"

#include <cmath>
#include <stdexcept>

namespace bb::course {

namespace {

/// The spin the seed's MatrixToVec3 reads back from the turn `spin` makes in one step: the
/// axis's length there is 2 sin(angle); below 0.001 it returns none.
Eigen::Vector3d read_back(const Eigen::Vector3d& spin, double dt) {
  const double angle = spin.norm() * dt;
  if (2.0 * std::abs(std::sin(angle)) < 0.001) return Eigen::Vector3d::Zero();
  return spin;
}

}  // namespace

SpinRule spin_rule(const std::string& name) {
  if (name == "free") return SpinRule::Free;
  if (name == "kinematic") return SpinRule::Kinematic;
  if (name == "shared") return SpinRule::Shared;
  throw std::invalid_argument("unknown spin rule '" + name + "'");
}

Eigen::Vector3d contact_spin(const Eigen::Vector3d& velocity, const Eigen::Vector3d& normal,
                             double radius) {
  const Eigen::Vector3d axis = velocity.cross(normal);
  const Eigen::Vector3d along = velocity - velocity.dot(normal) * normal;
  if (axis.norm() == 0.0 || radius <= 0.0) return Eigen::Vector3d::Zero();
  // The seed turns by -|v_p| / r about v x n: rolling, the contact point at rest.
  return -(along.norm() / radius) * axis.normalized();
}

void share_spins(Eigen::Vector3d& first, Eigen::Vector3d& second, double dt) {
  const Eigen::Vector3d half = 0.5 * (read_back(first, dt) - read_back(second, dt));
  first = half;
  second = -half;
}

}  // namespace bb::course
