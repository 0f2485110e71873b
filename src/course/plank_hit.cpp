#include "course/plank_hit.hpp"

namespace bb::course {

void seed_plank_hit(contact::HitBody& ball, contact::HitBody& plank, const Eigen::Vector3d& point,
                    const Eigen::Vector3d& normal) {
  // The ball's momentum along the normal becomes the plank's normal velocity...
  const double f = ball.mass * ball.velocity.dot(normal);
  plank.velocity += (f / plank.mass - plank.velocity.dot(normal)) * normal;
  // ...the ball goes back with its full normal speed...
  ball.velocity -= 2.0 * ball.velocity.dot(normal) * normal;
  // ...and the torque about the plank's centre, r x f, adds to its angular momentum.
  plank.spin = contact::spun(plank, (point - plank.position).cross(f * normal));
}

}  // namespace bb::course
