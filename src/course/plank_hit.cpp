#include "course/plank_hit.hpp"


namespace bb::course {

namespace {

/// The spin a torque impulse `angular` gives a body: J^-1 (J omega + angular).
Eigen::Vector3d spun(const HitBody& body, const Eigen::Vector3d& angular) {
  return body.inertia.ldlt().solve(body.inertia * body.spin + angular);
}

/// The hit's share of one body in the effective inverse mass along n at arm r.
double turning(const HitBody& body, const Eigen::Vector3d& r, const Eigen::Vector3d& n) {
  return n.dot(body.inertia.ldlt().solve(r.cross(n)).cross(r));
}

}  // namespace

void seed_plank_hit(HitBody& ball, HitBody& plank, const Eigen::Vector3d& point,
                    const Eigen::Vector3d& normal) {
  // The ball's momentum along the normal becomes the plank's normal velocity...
  const double f = ball.mass * ball.velocity.dot(normal);
  plank.velocity += (f / plank.mass - plank.velocity.dot(normal)) * normal;
  // ...the ball goes back with its full normal speed...
  ball.velocity -= 2.0 * ball.velocity.dot(normal) * normal;
  // ...and the torque about the plank's centre, r x f, adds to its angular momentum.
  plank.spin = spun(plank, (point - plank.position).cross(f * normal));
}

double impulse_hit(HitBody& a, HitBody& b, const Eigen::Vector3d& point,
                   const Eigen::Vector3d& normal, double restitution) {
  const Eigen::Vector3d ra = point - a.position, rb = point - b.position;
  const Eigen::Vector3d relative = a.velocity + a.spin.cross(ra) - b.velocity - b.spin.cross(rb);
  const double closing = relative.dot(normal);
  if (closing >= 0.0) return 0.0;
  const double j = -(1.0 + restitution) * closing /
                   (1.0 / a.mass + 1.0 / b.mass + turning(a, ra, normal) + turning(b, rb, normal));
  a.velocity += j / a.mass * normal;
  a.spin = spun(a, ra.cross(j * normal));
  b.velocity -= j / b.mass * normal;
  b.spin = spun(b, rb.cross(-j * normal));
  return j;
}

Eigen::Vector3d momentum(const HitBody& a, const HitBody& b) {
  return a.mass * a.velocity + b.mass * b.velocity;
}

Eigen::Vector3d angular_momentum(const HitBody& a, const HitBody& b,
                                 const Eigen::Vector3d& origin) {
  Eigen::Vector3d l = Eigen::Vector3d::Zero();
  for (const HitBody* body : {&a, &b})
    l += (body->position - origin).cross(body->mass * body->velocity) + body->inertia * body->spin;
  return l;
}

double kinetic_energy(const HitBody& a, const HitBody& b) {
  double e = 0.0;
  for (const HitBody* body : {&a, &b})
    e += 0.5 * body->mass * body->velocity.squaredNorm() +
         0.5 * body->spin.dot(body->inertia * body->spin);
  return e;
}

}  // namespace bb::course
