#include "contact/impulse_response.hpp"

namespace bb::contact {

namespace {}  // namespace

void apply_impulse(const Body& body, const Eigen::Vector3d& impulse, const Eigen::Vector3d* point,
                   const Eigen::Vector3d& position, const Eigen::Quaterniond& orientation,
                   Eigen::Vector3d& velocity, Eigen::Vector3d& spin) {
  velocity += impulse / body.mass;
  if (point == nullptr) return;
  const Eigen::Vector3d principal = principal_inertia(body);
  // A point mass has no inertia to turn: an off-centre push only moves it.
  if (principal.minCoeff() <= 0.0) return;
  const Eigen::Matrix3d r = orientation.normalized().toRotationMatrix();
  const Eigen::Matrix3d inertia = r * principal.asDiagonal() * r.transpose();
  spin += inertia.ldlt().solve((*point - position).cross(impulse));
}

void apply_impulse(const Body& body, const Impulse& impulse, const Eigen::Vector3d& position,
                   const Eigen::Quaterniond& orientation, Eigen::Vector3d& velocity,
                   Eigen::Vector3d& spin) {
  const Eigen::Vector3d point = impulse.point ? (*impulse.point) : Eigen::Vector3d::Zero();
  apply_impulse(body, impulse.impulse, impulse.point ? &point : nullptr, position, orientation,
                velocity, spin);
}

}  // namespace bb::contact
