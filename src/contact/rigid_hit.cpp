#include "contact/rigid_hit.hpp"

namespace bb::contact {

namespace {

double inverse_mass(const HitBody& body) {
  return body.mass > 0.0 ? 1.0 / body.mass : 0.0;
}

/// The hit's share of one body in the effective inverse mass along n at arm r: zero for
/// a fixed body, and for a body with no inertia to turn (a point).
double turning(const HitBody& body, const Eigen::Vector3d& r, const Eigen::Vector3d& n) {
  if (body.mass <= 0.0 || body.inertia.diagonal().minCoeff() <= 0.0) return 0.0;
  return n.dot(body.inertia.ldlt().solve(r.cross(n)).cross(r));
}

}  // namespace

HitBody hit_body(const Body& body, const Eigen::Vector3d& position,
                 const Eigen::Quaterniond& orientation, const Eigen::Vector3d& velocity,
                 const Eigen::Vector3d& spin) {
  const Eigen::Matrix3d r = orientation.normalized().toRotationMatrix();
  return {body.fixed ? 0.0 : body.mass, r * principal_inertia(body).asDiagonal() * r.transpose(),
          position, velocity, spin};
}

Eigen::Vector3d spun(const HitBody& body, const Eigen::Vector3d& angular) {
  if (body.inertia.diagonal().minCoeff() <= 0.0) return body.spin;
  return body.inertia.ldlt().solve(body.inertia * body.spin + angular);
}

double impulse_hit(HitBody& a, HitBody& b, const Eigen::Vector3d& point,
                   const Eigen::Vector3d& normal, double restitution) {
  const Eigen::Vector3d ra = point - a.position, rb = point - b.position;
  const Eigen::Vector3d relative = a.velocity + a.spin.cross(ra) - b.velocity - b.spin.cross(rb);
  const double closing = relative.dot(normal);
  if (closing >= 0.0) return 0.0;
  const double j =
      -(1.0 + restitution) * closing /
      (inverse_mass(a) + inverse_mass(b) + turning(a, ra, normal) + turning(b, rb, normal));
  // A fixed body takes the impulse without moving.
  if (a.mass > 0.0) {
    a.velocity += j / a.mass * normal;
    a.spin = spun(a, ra.cross(j * normal));
  }
  if (b.mass > 0.0) {
    b.velocity -= j / b.mass * normal;
    b.spin = spun(b, rb.cross(-j * normal));
  }
  return j;
}

double friction_hit(HitBody& a, HitBody& b, const Eigen::Vector3d& point,
                    const Eigen::Vector3d& normal, double normal_impulse, double mu_static,
                    double mu_kinetic) {
  const Eigen::Vector3d ra = point - a.position, rb = point - b.position;
  const Eigen::Vector3d relative = a.velocity + a.spin.cross(ra) - b.velocity - b.spin.cross(rb);
  const Eigen::Vector3d slip = relative - relative.dot(normal) * normal;
  if (slip.norm() == 0.0 || normal_impulse <= 0.0) return 0.0;
  const Eigen::Vector3d t = slip.normalized();
  const double k = inverse_mass(a) + inverse_mass(b) + turning(a, ra, t) + turning(b, rb, t);
  if (k <= 0.0) return 0.0;
  // Sticking needs |slip| / k; the surfaces hold it up to mu_s j_n, else slide at mu_k j_n.
  const double stick = slip.norm() / k;
  const double j = stick <= mu_static * normal_impulse ? stick : mu_kinetic * normal_impulse;
  if (a.mass > 0.0) {
    a.velocity -= j / a.mass * t;
    a.spin = spun(a, ra.cross(-j * t));
  }
  if (b.mass > 0.0) {
    b.velocity += j / b.mass * t;
    b.spin = spun(b, rb.cross(j * t));
  }
  return j;
}

Eigen::Vector3d momentum(const HitBody& a, const HitBody& b) {
  return a.mass * a.velocity + b.mass * b.velocity;
}

Eigen::Vector3d angular_momentum(const HitBody& a, const HitBody& b,
                                 const Eigen::Vector3d& origin) {
  Eigen::Vector3d l = Eigen::Vector3d::Zero();
  for (const HitBody* body : {&a, &b})
    if (body->mass > 0.0)
      l +=
          (body->position - origin).cross(body->mass * body->velocity) + body->inertia * body->spin;
  return l;
}

double kinetic_energy(const HitBody& a, const HitBody& b) {
  double e = 0.0;
  for (const HitBody* body : {&a, &b})
    if (body->mass > 0.0)
      e += 0.5 * body->mass * body->velocity.squaredNorm() +
           0.5 * body->spin.dot(body->inertia * body->spin);
  return e;
}

}  // namespace bb::contact
