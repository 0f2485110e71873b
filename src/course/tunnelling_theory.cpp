#include "course/tunnelling_theory.hpp"

#include <Eigen/Geometry>
#include <cmath>

#include "model/contact_pairs.hpp"

namespace bb {

namespace {

/// Nothing acts on the bodies but their contacts: a ball flies at its starting velocity.
bool only_contacts_act(const World& world) {
  if (world.gravity.norm() > 0.0 || world.air || world.water || world.grid || world.waves ||
      !world.springs.empty() || !world.hinges.empty() || !world.impulses.empty())
    return false;
  for (const Body& b : world.bodies)
    if (b.force.norm() > 0.0 || b.torque.norm() > 0.0 || b.wind_force.norm() > 0.0) return false;
  return true;
}

/// The one body that moves, -1 when none or several do.
int only_moving_body(const World& world) {
  int moving = -1;
  for (std::size_t i = 0; i < world.bodies.size(); ++i)
    if (!world.bodies[i].fixed) {
      if (moving >= 0) return -1;
      moving = static_cast<int>(i);
    }
  return moving;
}

}  // namespace

std::optional<double> surely_turned_back_step(const World& world) {
  if (!only_contacts_act(world)) return std::nullopt;
  const int ball = only_moving_body(world);
  if (ball < 0 || world.bodies[ball].shape != Shape::Sphere) return std::nullopt;
  const Body& b = world.bodies[ball];
  const double speed = b.velocity.norm();
  if (speed == 0.0) return std::nullopt;
  for (const ContactPair& pair : contact_pairs(world)) {
    if (pair.a != ball || pair.ground() || world.bodies[pair.b].shape != Shape::Box) continue;
    const Body& box = world.bodies[pair.b];
    if (!box.fixed) continue;
    // In the box's frame: the path along one of its axes, through the face across it.
    const Eigen::Matrix3d to_box = box.orientation.normalized().toRotationMatrix().transpose();
    const Eigen::Vector3d dir = to_box * b.velocity / speed;
    const Eigen::Vector3d start = to_box * (b.position - box.position);
    Eigen::Index axis = 0;
    if (dir.cwiseAbs().maxCoeff(&axis) < 1.0 - 1e-12) continue;
    bool through_face = true;
    for (Eigen::Index k = 0; k < 3; ++k)
      if (k != axis && std::abs(start[k]) >= box.half_extents[k]) through_face = false;
    const double window = box.half_extents[axis] + b.radius;
    // Starting before the near half, flying towards the box.
    if (!through_face || start[axis] * dir[axis] > -window) continue;
    return window / speed;
  }
  return std::nullopt;
}

}  // namespace bb
