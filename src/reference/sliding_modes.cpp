#include "reference/sliding_modes.hpp"

#include <cmath>

#include "contact/contact_geometry.hpp"
#include "model/contact_pairs.hpp"
#include "model/text.hpp"
#include "reference/scene_model.hpp"

namespace bb {

namespace {

Eigen::Vector3d tangential(const Eigen::Vector3d& v, const Eigen::Vector3d& n) {
  return v - v.dot(n) * n;
}

}  // namespace

SlideDecision decide_slide(double mu_static, const Eigen::Vector3d& n, const Eigen::Vector3d& v,
                           const Eigen::Vector3d& a, const std::string& body, double t) {
  const Eigen::Vector3d slide = tangential(v, n), push = tangential(a, n);
  SlideDecision d;
  if (slide.norm() > 0.0) {
    d = {SlideMode::Sliding, slide.normalized()};
  } else if (push.norm() <= mu_static * -a.dot(n)) {
    return {SlideMode::Stuck, Eigen::Vector3d::Zero()};
  } else {
    d = {SlideMode::Sliding, push.normalized()};
  }
  // A tangential force across the sliding direction would curve the path.
  const double across = (push - push.dot(d.direction) * d.direction).norm();
  if (across > 1e-9 * std::max(1.0, a.norm()))
    throw BeyondExactAnswer("at t = " + short_number(t) + " s body '" + body +
                            "' slides across the force along the ground (" + short_number(across) +
                            " m/s^2 across its path): the reference models straight slides only");
  return d;
}

std::string tipping_reason(const World& scene, const Body& box) {
  const int index = static_cast<int>(&box - scene.bodies.data());
  const std::optional<ContactPair> g = ground_pair(scene, index);
  if (!g || box.shape != Shape::Box) return "";
  const Eigen::Vector3d n = scene.ground->normal;
  // The box's axis along the normal is its height; the other two its widths.
  const Eigen::Vector3d local = box.orientation.conjugate() * n;
  Eigen::Index up = 0;
  local.cwiseAbs().maxCoeff(&up);
  const double h = box.half_extents[up];
  double w = INFINITY;
  for (Eigen::Index k = 0; k < 3; ++k)
    if (k != up) w = std::min(w, box.half_extents[k]);
  const double press = -scene.gravity.dot(n);
  const double slope = press > 0.0 ? tangential(scene.gravity, n).norm() / press : INFINITY;
  // It slides at some time when it starts sliding, is pushed, or the slope beats mu_s.
  bool slides = tangential(box.velocity, n).norm() > 0.0 || slope > g->friction_static;
  for (const Impulse& i : scene.impulses) slides = slides || i.body == index;
  const double ratio =
      std::max(slides ? g->friction_kinetic : 0.0, slope <= g->friction_static ? slope : 0.0);
  if (h * ratio <= w) return "";
  return "box '" + box.name + "' may tip over an edge: friction at its face " + short_number(h) +
         " m below its centre against " + short_number(ratio) +
         " of its weight's normal part beats " + "its half width " + short_number(w) +
         " m (tipping has no event model in the reference)";
}

std::string box_slide_reason(const World& scene, int index) {
  const Body& box = scene.bodies[index];
  const std::string name = "moving box '" + box.name + "' ";
  // Away from any ground a ball's hit on the box is one point, resolved by the impulse.
  for (const ContactPair& p : contact_pairs(scene))
    if (!p.ground() && (p.a == index || p.b == index) &&
        (scene.ground || scene.bodies[p.a].shape == Shape::Box)) {
      const Body& other = scene.bodies[p.a == index ? p.b : p.a];
      return name + "can touch " + (other.fixed ? "fixed " : "moving ") + "body '" + other.name +
             "'" + (scene.ground ? " while there is a ground" : "") +
             ": a box's contacts with another body (faces, edges, tipping) have no event model "
             "in the reference";
    }
  if (!scene.ground) return "";
  for (const Spring& s : scene.springs)
    if (s.body_a == index || s.body_b == index)
      return name + "hangs on a spring while on the ground: not modelled by the reference";
  const Eigen::Vector3d n = scene.ground->normal;
  const contact::Proximity p =
      contact::box_plane(box.position, box.orientation, box.half_extents, scene.ground->point, n);
  const Eigen::Vector3d local = box.orientation.conjugate() * n;
  if (std::abs(p.gap) > 1e-9 || local.cwiseAbs().maxCoeff() < 1.0 - 1e-12)
    return name +
           "does not start flat on a face on the ground: falling and landing boxes have "
           "no event model in the reference";
  if (std::abs(box.velocity.dot(n)) > kRestingNormalSpeed || box.angular_velocity.norm() > 0.0)
    return name +
           "starts moving off the ground or spinning: the reference slides boxes flat "
           "on the ground only";
  if (scene.gravity.dot(n) >= 0.0)
    return name + "is not pressed onto the ground by gravity: not modelled by the reference";
  for (const Impulse& i : scene.impulses)
    if (i.body == index && (i.point || i.impulse.dot(n) != 0.0))
      return name + "is pushed off its centre or off the ground's plane (impulse at line " +
             std::to_string(i.line) + "): the reference slides boxes flat on the ground only";
  return tipping_reason(scene, box);
}

}  // namespace bb
