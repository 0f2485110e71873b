#include "course/hinge_turning.hpp"

#include "contact/contact_geometry.hpp"
#include "course/plank_inertia.hpp"
#include "model/contact_pairs.hpp"
#include "model/vec3.hpp"

namespace bb::course {

namespace {

/// The seed's J for `body` about `hinge`: a box as a plank along its longest side, split
/// at the axis; any other shape its true inertia about the axis (parallel axes).
double seed_inertia(const Body& body, const Hinge& hinge) {
  const Vec3 r = body.position - hinge.anchor;
  const Vec3 across = r - r.dot(hinge.axis) * hinge.axis;
  if (body.shape == Shape::Box) {
    Eigen::Index k = 0;
    body.half_extents.maxCoeff(&k);
    Vec3 unit = Vec3::Zero();
    unit[k] = 1.0;
    const Vec3 along = body.orientation * unit;
    return seed_axis_inertia(body.mass, 2.0 * body.half_extents[k],
                             (hinge.anchor - body.position).dot(along));
  }
  const Vec3 local = body.orientation.conjugate() * hinge.axis;
  return local.dot(principal_inertia(body).asDiagonal() * local) + body.mass * across.squaredNorm();
}

}  // namespace

HingeTurning::HingeTurning(const World& scene) : scene_(scene) {
  for (const Hinge& h : scene.hinges) {
    const Body& b = scene.bodies[h.body];
    hinges_.push_back(&h);
    inertia_.push_back(seed_inertia(b, h));
    momentum_.push_back(inertia_.back() * b.angular_velocity.dot(h.axis));
    const std::optional<ContactPair> ground = ground_pair(scene, h.body);
    const bool lands = ground && b.shape == Shape::Box;
    ground_restitution_.push_back(lands ? ground->restitution : -1.0);
  }
}

void HingeTurning::step(double dt, const std::vector<Vec3>& a, std::vector<Vec3>& x,
                        std::vector<Vec3>& v, std::vector<Quat>& q, std::vector<Vec3>& spin) {
  for (std::size_t k = 0; k < hinges_.size(); ++k) {
    const Hinge& h = *hinges_[k];
    const int i = h.body;
    const Vec3 r = x[i] - h.anchor;
    // Seed: L = L + T dt, omega = L / J, then the turn by omega dt.
    momentum_[k] += r.cross(scene_.bodies[i].mass * a[i]).dot(h.axis) * dt;
    double omega = momentum_[k] / inertia_[k];
    const Quat turn = quat_from_axis_angle(h.axis, omega * dt);
    const Vec3 turned_x = h.anchor + turn * r;
    const Quat turned_q = (turn * q[i]).normalized();
    // Into the ground: the step is not taken and the spin turns back (section 3's clamp).
    if (ground_restitution_[k] >= 0.0 && into_ground(i, h, x[i], q[i], turned_x, turned_q)) {
      momentum_[k] *= -ground_restitution_[k];
      omega = momentum_[k] / inertia_[k];
    } else {
      x[i] = turned_x;
      q[i] = turned_q;
    }
    spin[i] = omega * h.axis;
    v[i] = spin[i].cross(x[i] - h.anchor);
  }
}

bool HingeTurning::into_ground(int i, const Hinge& h, const Vec3& x0, const Quat& q0,
                               const Vec3& x1, const Quat& q1) const {
  const Ground& g = *scene_.ground;
  const Vec3& half = scene_.bodies[i].half_extents;
  const double after = contact::clear_height(x1, q1, half, h.anchor, h.axis, g.point, g.normal);
  if (after >= 0.0) return false;
  return after < contact::clear_height(x0, q0, half, h.anchor, h.axis, g.point, g.normal);
}

bool HingeTurning::push(const Impulse& impulse, std::vector<Vec3>& x, std::vector<Vec3>& v,
                        std::vector<Vec3>& spin) {
  for (std::size_t k = 0; k < hinges_.size(); ++k) {
    const Hinge& h = *hinges_[k];
    if (h.body != impulse.body) continue;
    const int i = h.body;
    const Vec3 point = impulse.point.value_or(x[i]);
    momentum_[k] += (point - h.anchor).cross(impulse.impulse).dot(h.axis);
    spin[i] = momentum_[k] / inertia_[k] * h.axis;
    v[i] = spin[i].cross(x[i] - h.anchor);
    return true;
  }
  return false;
}

}  // namespace bb::course
