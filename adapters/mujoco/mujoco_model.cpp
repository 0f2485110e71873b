#include "mujoco_model.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "../engine_friction.hpp"
#include "../point_body.hpp"
#include "model/contact_pairs.hpp"

namespace bb {

MujocoContact mujoco_contact(double restitution, double dt) {
  // A linear spring and damper x'' = -b x' - k x rebounds at exp(-zeta pi / sqrt(1 - zeta^2))
  // of its approach speed, zeta = b / (2 sqrt(k)): the damping ratio that gives e.
  const double log_e = std::log(std::max(restitution, 1e-12));
  const double zeta = restitution >= 1.0
                          ? 0.0
                          : -log_e / std::sqrt(std::numbers::pi * std::numbers::pi + log_e * log_e);
  const double omega = 1.0 / std::max(kMujocoContactTime, 2.0 * dt);
  return {omega * omega, 2.0 * zeta * omega, zeta};
}

const Hinge* hinge_of(const World& world, std::size_t body) {
  const Hinge* found = nullptr;
  for (const Hinge& h : world.hinges) {
    if (h.body != static_cast<int>(body)) continue;
    if (found != nullptr)
      throw std::runtime_error("the MuJoCo adapter builds one hinge per body; body " +
                               world.bodies[body].name + " has two");
    found = &h;
  }
  return found;
}

namespace {

/// A moving body's joints: a hinge about its [[hinge]]'s axis through the anchor (in the
/// body's frame, the body placed as it starts), else a free joint in 3D or two slides and
/// a hinge about z in 2D (the body placed at the origin, its joints' positions set later).
std::string joints_and_place(const World& world, std::size_t i) {
  const Body& b = world.bodies[i];
  if (const Hinge* h = hinge_of(world, i)) {
    const Quat q = b.orientation.normalized();
    const Vec3 anchor = q.conjugate() * (h->anchor - b.position);
    const Vec3 axis = q.conjugate() * h->axis;
    return fmt::format(
        "    <body name=\"b{}\" pos=\"{:.17g} {:.17g} {:.17g}\" quat=\"{:.17g} {:.17g} {:.17g} "
        "{:.17g}\">\n"
        "      <joint type=\"hinge\" pos=\"{:.17g} {:.17g} {:.17g}\" axis=\"{:.17g} {:.17g} "
        "{:.17g}\" limited=\"false\" damping=\"0\" armature=\"0\" stiffness=\"0\" "
        "frictionloss=\"0\"/>\n",
        i, b.position.x(), b.position.y(), b.position.z(), q.w(), q.x(), q.y(), q.z(), anchor.x(),
        anchor.y(), anchor.z(), axis.x(), axis.y(), axis.z());
  }
  std::string xml = fmt::format("    <body name=\"b{}\">\n", i);
  if (world.dims == 3) return xml + "      <freejoint/>\n";
  return xml +
         "      <joint type=\"slide\" axis=\"1 0 0\"/>\n"
         "      <joint type=\"slide\" axis=\"0 1 0\"/>\n"
         "      <joint type=\"hinge\" axis=\"0 0 1\"/>\n";
}

/// The <pair> of body `pair.a` with the ground or with body `pair.b`: its restitution as the
/// damping ratio of a spring and damper in MuJoCo's direct form, solref = (-k, -b), the
/// impedance at its largest so that the reference acceleration is followed; friction the
/// engine coefficient along both tangents (condim 3), or none (condim 1).
std::string contact_pair(const ContactPair& pair, double dt) {
  const MujocoContact c = mujoco_contact(pair.restitution, dt);
  const double mu = engine_friction(pair);
  const std::string other = pair.ground() ? "ground" : fmt::format("g{}", pair.b);
  return fmt::format(
      "    <pair geom1=\"g{}\" geom2=\"{}\" condim=\"{}\" friction=\"{:.17g} {:.17g} 0 0 0\" "
      "solref=\"{:.17g} {:.17g}\" solimp=\"{} {} 0.001 0.5 2\" margin=\"{:.17g}\" gap=\"0\"/>\n",
      pair.a, other, mu > 0.0 ? 3 : 1, mu, mu, -c.stiffness, -c.damping, kMujocoImpedance,
      kMujocoImpedance, kMujocoMargin);
}

/// Body i's sphere or box geom, for the pairs it is in; no pair is automatic (contype 0).
std::string geom_of(const Body& b, std::size_t i) {
  if (b.shape == Shape::Sphere)
    return fmt::format(
        "      <geom name=\"g{}\" type=\"sphere\" size=\"{:.17g}\" contype=\"0\" "
        "conaffinity=\"0\" mass=\"0\"/>\n",
        i, b.radius);
  if (b.shape == Shape::Box)
    return fmt::format(
        "      <geom name=\"g{}\" type=\"box\" size=\"{:.17g} {:.17g} {:.17g}\" contype=\"0\" "
        "conaffinity=\"0\" mass=\"0\"/>\n",
        i, b.half_extents.x(), b.half_extents.y(), b.half_extents.z());
  return "";
}

/// Whether two things may touch, and so get geoms and a <pair>: a point body never does (as
/// in the other engines, it has no shape to collide with).
bool collides(const World& world, const ContactPair& pair) {
  return world.bodies[pair.a].shape != Shape::Point &&
         (pair.ground() || world.bodies[pair.b].shape != Shape::Point);
}

/// Each spring as a spatial tendon between the sites at its bodies' centres: MuJoCo's own
/// spring (stiffness, rest length `springlength`) and damper along the tendon.
std::string spring_tendons(const World& world) {
  if (world.springs.empty()) return "";
  std::string xml = "  <tendon>\n";
  for (const Spring& s : world.springs)
    xml += fmt::format(
        "    <spatial stiffness=\"{:.17g}\" damping=\"{:.17g}\" springlength=\"{:.17g}\" "
        "limited=\"false\"><site site=\"s{}\"/><site site=\"s{}\"/></spatial>\n",
        s.stiffness, s.damping, s.rest_length, s.body_a, s.body_b);
  return xml + "  </tendon>\n";
}

}  // namespace

std::string mujoco_model_xml(const World& world, double dt, const std::string& integrator) {
  // MuJoCo's own fluid forces off: drag, Magnus and wind come from the force model. The
  // friction cone elliptic: Coulomb's circle, as the reference has it.
  std::string xml = fmt::format(
      "<mujoco model=\"beachball\">\n"
      "  <option timestep=\"{:.17g}\" gravity=\"{:.17g} {:.17g} {:.17g}\" integrator=\"{}\" "
      "density=\"0\" viscosity=\"0\" cone=\"elliptic\"/>\n"
      "  <worldbody>\n",
      dt, world.gravity.x(), world.gravity.y(), world.gravity.z(), integrator);
  // The ground, touched only through the pairs below.
  if (world.ground)
    xml += fmt::format(
        "    <geom name=\"ground\" type=\"plane\" size=\"0 0 1\" pos=\"{:.17g} {:.17g} {:.17g}\" "
        "zaxis=\"{:.17g} {:.17g} {:.17g}\" contype=\"0\" conaffinity=\"0\"/>\n",
        world.ground->point.x(), world.ground->point.y(), world.ground->point.z(),
        world.ground->normal.x(), world.ground->normal.y(), world.ground->normal.z());
  const std::vector<ContactPair> pairs = contact_pairs(world);
  std::vector<bool> touches(world.bodies.size(), false);
  for (const ContactPair& pair : pairs) {
    if (!collides(world, pair)) continue;
    touches[pair.a] = true;
    if (!pair.ground()) touches[pair.b] = true;
  }
  for (std::size_t i = 0; i < world.bodies.size(); ++i) {
    const Body& b = world.bodies[i];
    // A fixed body is part of the world (with its shape, and the site a spring ends at).
    if (b.fixed) {
      const Quat q = b.orientation.normalized();
      xml += fmt::format(
          "    <body name=\"b{}\" pos=\"{:.17g} {:.17g} {:.17g}\" quat=\"{:.17g} {:.17g} {:.17g} "
          "{:.17g}\"><site name=\"s{}\"/>\n",
          i, b.position.x(), b.position.y(), b.position.z(), q.w(), q.x(), q.y(), q.z(), i);
      if (touches[i]) xml += geom_of(b, i);
      xml += "    </body>\n";
      continue;
    }
    const Vec3 inertia = engine_inertia(b);
    xml += joints_and_place(world, i);
    xml += fmt::format(
        "      <inertial pos=\"0 0 0\" mass=\"{:.17g}\" diaginertia=\"{:.17g} {:.17g} "
        "{:.17g}\"/>\n",
        b.mass, inertia.x(), inertia.y(), inertia.z());
    if (touches[i]) xml += geom_of(b, i);
    // The site at its centre, where its springs end.
    if (!world.springs.empty()) xml += fmt::format("      <site name=\"s{}\"/>\n", i);
    xml += "    </body>\n";
  }
  xml += "  </worldbody>\n";
  xml += spring_tendons(world);
  std::string written;
  for (const ContactPair& pair : pairs)
    if (collides(world, pair)) written += contact_pair(pair, dt);
  if (!written.empty()) xml += "  <contact>\n" + written + "  </contact>\n";
  return xml + "</mujoco>\n";
}

}  // namespace bb
