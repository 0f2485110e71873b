// Which scenes the reference can answer exactly, and why not the others: the reasons a
// scene is beyond its event model, checked before it starts.
#include <algorithm>
#include <cmath>

#include "contact/contact_geometry.hpp"
#include "reference/gsl_reference.hpp"
#include "reference/scene_model.hpp"
#include "reference/scene_model_state.hpp"
#include "reference/sliding_modes.hpp"

namespace bb {

using namespace state_view;

namespace {

/// Why the reference cannot turn the scene's hinged bodies exactly ("" when it can): one
/// hinge per body, touching nothing, on no spring, starting at rest or turning about the
/// hinge.
std::string hinge_reason(const World& scene) {
  const std::vector<ContactPair> pairs = contact_pairs(scene);
  for (const Hinge& h : scene.hinges) {
    const Body& b = scene.bodies[h.body];
    const std::string name =
        "body '" + b.name + "' on the [[hinge]] at line " + std::to_string(h.line);
    for (const Hinge& other : scene.hinges)
      if (&other != &h && other.body == h.body)
        return name + " has a second hinge: not modelled by the reference";
    // A box on the ground turning about a hinge lands on it (the falling wall); it takes no
    // other contact.
    for (const ContactPair& p : pairs)
      if ((p.a == h.body || p.b == h.body) && !(p.ground() && b.shape == Shape::Box))
        return name +
               " can touch another body: a hinged body's contacts other than a box's with the "
               "ground have no event model in the reference";
    for (const Impulse& i : scene.impulses)
      if (i.body == h.body && ground_pair(scene, h.body))
        return name + " is pushed (the [[impulse]] at line " + std::to_string(i.line) +
               ") while it can land on the ground: not modelled by the reference";
    for (const Spring& s : scene.springs)
      if (s.body_a == h.body || s.body_b == h.body)
        return name + " hangs on a spring: not modelled by the reference";
    const Vector3d spin_across = b.angular_velocity - b.angular_velocity.dot(h.axis) * h.axis;
    const Vector3d follows = b.angular_velocity.cross(b.position - h.anchor);
    if (spin_across.norm() > 1e-12 || (b.velocity - follows).norm() > 1e-12)
      return name + " starts moving other than by turning about its hinge";
  }
  return "";
}

/// Why the reference cannot turn a body by its torque exactly ("" when it can): the torque
/// is exact in free flight; at a contact or on a hinge its turn has no event model.
std::string torque_reason(const World& scene) {
  const std::vector<ContactPair> pairs = contact_pairs(scene);
  for (std::size_t i = 0; i < scene.bodies.size(); ++i) {
    const Body& b = scene.bodies[i];
    if (b.torque.isZero()) continue;
    const int body = static_cast<int>(i);
    for (const Hinge& h : scene.hinges)
      if (h.body == body)
        return "body '" + b.name + "' has a torque of its own and turns on the [[hinge]] at line " +
               std::to_string(h.line) + ": not modelled by the reference";
    for (const ContactPair& p : pairs)
      if (p.a == body || p.b == body)
        return "body '" + b.name +
               "' has a torque of its own and can touch something: a turning body's contacts "
               "have no event model in the reference";
  }
  return "";
}

/// What `body` is, in a reason: "ball", "box" or "point".
std::string shape_word(const Body& body) {
  if (body.shape == Shape::Sphere) return "ball";
  return body.shape == Shape::Box ? "box" : "point";
}

/// Whether body `i` starts touching the ground, not moving along its normal.
bool starts_resting(const World& scene, int i) {
  const std::optional<ContactPair> pair = ground_pair(scene, i);
  if (!pair) return false;
  const Body& b = scene.bodies[i];
  const contact::Proximity p =
      contact::measure(scene, *pair, b.position, b.position, b.orientation);
  return std::abs(p.gap) <= kSimultaneousGap &&
         std::abs(b.velocity.dot(scene.ground->normal)) <= 1e-12;
}

}  // namespace

std::string SceneModel::beyond_exact_answer(const World& scene) {
  if (!scene.springs.empty() && scene.bodies.size() > kMaxReferenceBodies)
    return std::to_string(scene.bodies.size()) +
           " bodies on springs: a reference to 1e-10 would take longer than a report allows "
           "(it is solved up to " +
           std::to_string(kMaxReferenceBodies) + " bodies)";
  // A crowd of bodies that can touch each other ends in piles and simultaneous contacts.
  std::vector<char> touches(scene.bodies.size(), 0);
  for (const ContactPair& p : contact_pairs(scene))
    if (!p.ground() && !scene.bodies[p.b].fixed) touches[p.a] = touches[p.b] = 1;
  const auto crowd = static_cast<std::size_t>(std::count(touches.begin(), touches.end(), 1));
  if (crowd > kMaxTouchingBodies)
    return std::to_string(crowd) +
           " moving bodies can touch each other: a crowd piles up and touches at many points at "
           "once, which has no exact answer (the reference takes up to " +
           std::to_string(kMaxTouchingBodies) + ")";
  // Friction at an impact is exact where a ball meets something that does not move.
  for (const ContactPair& p : contact_pairs(scene)) {
    const bool rubs = p.friction_static > 0.0 || p.friction_kinetic > 0.0;
    if (!rubs || p.ground()) continue;
    const Body &a = scene.bodies[p.a], &b = scene.bodies[p.b];
    if (a.shape == Shape::Sphere && b.fixed) continue;
    if (b.fixed)
      return shape_word(a) + " '" + a.name + "' touches fixed body '" + b.name +
             "' with friction: the reference has friction against a fixed body only for a "
             "ball's impacts; a " +
             shape_word(a) +
             " sliding or resting on another body (faces, edges, tipping) has no event model "
             "in the reference";
    return "bodies '" + a.name + "' and '" + b.name +
           "' touch with friction and both move: friction between two moving bodies has no "
           "event model in the reference";
  }
  if (const std::string why = hinge_reason(scene); !why.empty()) return why;
  if (const std::string why = torque_reason(scene); !why.empty()) return why;
  const bool touching = scene.ground || !scene.contacts.empty();
  for (std::size_t i = 0; i < scene.bodies.size(); ++i) {
    const Body& b = scene.bodies[i];
    if (!touching || b.fixed) continue;
    const std::optional<ContactPair> on_ground = ground_pair(scene, static_cast<int>(i));
    const bool rubs =
        on_ground && (on_ground->friction_static > 0.0 || on_ground->friction_kinetic > 0.0);
    // A ball bouncing on a ground with friction is one impact at a time; one that rests
    // on it would roll.
    if (b.shape == Shape::Sphere && rubs && starts_resting(scene, static_cast<int>(i)))
      return "body '" + b.name +
             "' is a ball resting on a ground with friction: it would roll, and rolling has no "
             "model in the reference";
    if (b.shape != Shape::Box) continue;
    if (const std::string why = box_slide_reason(scene, static_cast<int>(i)); !why.empty())
      return why;
  }
  // Bodies that start touching each other (a stack, a ball resting on another) press on
  // each other at once: no single event resolves that.
  const std::vector<double> y = SceneModel(scene).initial_state();
  for (const ContactPair& pair : contact_pairs(scene)) {
    if (pair.ground()) continue;
    const Body& b = scene.bodies[pair.b];
    const contact::Proximity p = contact::measure(scene, pair, Vector3d(y.data() + at(pair.a)),
                                                  Vector3d(y.data() + at(pair.b)), b.orientation);
    if (p.gap <= kSimultaneousGap)
      return "bodies '" + scene.bodies[pair.a].name + "' and '" + b.name +
             "' touch at the start: resting contact between bodies has no event model in the "
             "reference";
  }
  return "";
}

}  // namespace bb
