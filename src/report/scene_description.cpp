#include "report/scene_description.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "report/format.hpp"
#include "report/scene_interactions.hpp"
#include "report/table.hpp"

namespace bb {

namespace {

std::string shape_cell(const Body& b) {
  switch (b.shape) {
    case Shape::Sphere:
      return fmt::format("{} r = {:g} m", b.shell ? "shell" : "solid sphere", b.radius);
    case Shape::Box:
      return fmt::format("box {:g} x {:g} x {:g} m", 2 * b.half_extents.x(), 2 * b.half_extents.y(),
                         2 * b.half_extents.z());
    case Shape::Point:
      return "point";
  }
  return "?";
}

std::string friction(double mu_static, double mu_kinetic) {
  if (mu_static == 0.0 && mu_kinetic == 0.0) return "none";
  return fmt::format("mu_s {:g}, mu_k {:g}", mu_static, mu_kinetic);
}

/// The ground: where, how tilted (the angle of its normal from the vertical against
/// gravity), and its restitution and friction.
std::string ground_line(const Scene& scene) {
  const Ground& g = *scene.ground;
  const double gravity = scene.gravity.norm();
  const Vec3 up = gravity > 0.0 ? Vec3(-scene.gravity / gravity) : Vec3::UnitY();
  const double slope = std::acos(std::clamp(g.normal.dot(up), -1.0, 1.0)) * 180.0 / M_PI;
  return fmt::format(
      "- a ground plane through {} with normal {} ({}), restitution {:g}, friction {}\n",
      format_vector(g.point, scene.dims), format_vector(g.normal, scene.dims),
      slope < 1e-9 ? std::string("level") : fmt::format("a slope of {:.4g} degrees", slope),
      g.restitution, friction(g.friction_static, g.friction_kinetic));
}

/// A boat's line (seed section 9): its heading, its sail and its hull, where it has them.
std::string boat_line(const Body& b) {
  const double heading = 2.0 * std::atan2(b.orientation.z(), b.orientation.w()) * 180.0 / M_PI;
  std::string out = fmt::format("- boat {}: heading {:g} degrees", b.name, heading);
  if (const std::optional<Sail>& s = b.sail) {
    out += fmt::format("; sail {:g} m^2, C_s {:g}, at {:g} degrees from the heading", s->area,
                       s->coefficient, s->angle);
    if (s->heel_stiffness > 0.0)
      out += fmt::format(", heeling by F_across / {:g} N/rad", s->heel_stiffness);
  }
  if (const std::optional<Hull>& h = b.hull)
    out += h->no_drift
               ? fmt::format(
                     "; hull drag areas C A ahead {:g}, astern {:g} m^2, and no "
                     "drift: the keel cancels every sideways force",
                     h->forward, h->backward)
               : fmt::format("; hull drag areas C A ahead {:g}, astern {:g}, across {:g} m^2",
                             h->forward, h->backward, h->sideways);
  return out + "\n";
}

/// A wind panel's line (seed section 8, "Wind"): the law of its push and its numbers.
std::string plate_line(const Body& b) {
  const Plate& p = *b.plate;
  return p.law == PlateLaw::Course
             ? fmt::format(
                   "- panel {}: pushed along its normal n by the course text's law F = k a "
                   "((w - v) . n) n, k {:g} N s/m^3, a {:g} m^2, at its centre (no "
                   "torque: its spin is kept)\n",
                   b.name, p.k, p.area)
             : fmt::format(
                   "- panel {}: pushed along its normal n by the flat-plate law F = 1/2 "
                   "rho C a ((w - v) . n) |(w - v) . n| n, C {:g}, a {:g} m^2, at its "
                   "centre (no torque: its spin is kept)\n",
                   b.name, p.coefficient, p.area);
}

/// How a body starts turned: degrees about z in 2D, about an axis in 3D; "-" unturned.
std::string turned_cell(const Body& b, int dims) {
  const Eigen::AngleAxisd turn(b.orientation);
  if (turn.angle() == 0.0) return "-";
  const double degrees = turn.angle() * 180.0 / M_PI;
  if (dims == 2) return fmt::format("{:g} deg", turn.axis().z() < 0.0 ? -degrees : degrees);
  return fmt::format("{:g} deg about {}", degrees, format_vector(turn.axis(), 3));
}

/// The bodies' table, headers only; with `turned` a column for how each starts turned.
Table bodies_table(bool turned) {
  Table t;
  t.headers = {"body",     "shape",      "mass kg",      "Cd",
               "magnus k", "position m", "velocity m/s", "spin rad/s"};
  t.right_aligned = {false, false, true, true, true, false, false, false};
  if (turned) {
    t.headers.push_back("turned");
    t.right_aligned.push_back(false);
  }
  return t;
}

std::vector<std::string> body_row(const Scene& scene, const Body& b, bool turned) {
  std::vector<std::string> row = {b.name,
                                  shape_cell(b),
                                  b.fixed ? "fixed" : fmt::format("{:g}", b.mass),
                                  fmt::format("{:g}", b.drag_coefficient),
                                  fmt::format("{:g}", b.magnus),
                                  format_vector(b.position, scene.dims),
                                  format_vector(b.velocity, scene.dims),
                                  scene.dims == 2 ? fmt::format("{:g}", b.angular_velocity.z())
                                                  : format_vector(b.angular_velocity, 3)};
  if (turned) row.push_back(turned_cell(b, scene.dims));
  return row;
}

}  // namespace

std::string describe_scene(const Scene& scene) {
  std::string dts;
  for (double d : scene.dt) dts += (dts.empty() ? "" : ", ") + format_dt(d);
  std::string out = fmt::format(
      "- {}D, {:g} s simulated, sampled every {} s\n- steps swept: {} s; tables and gates use "
      "report_dt = {} s\n- gravity {} m/s^2\n",
      scene.dims, scene.duration, format_dt(scene.sample), dts, format_dt(scene.report_dt),
      format_vector(scene.gravity, scene.dims));
  if (scene.air)
    out += fmt::format(
        "- air density {:g} kg/m^3, wind {} m/s; drag F = -1/2 Cd A rho |v - w| (v - w), "
        "A = pi r^2; Magnus F = k (omega x (v - w))\n",
        scene.air->density, format_vector(scene.air->wind, scene.dims));
  else
    out += "- no air: no drag, no wind, no Magnus\n";
  if (scene.water)
    out += fmt::format(
        "- still water, density {:g} kg/m^3: the x-y plane seen from above, holding the boats "
        "up\n",
        scene.water->density);
  for (const Body& b : scene.bodies)
    if (b.sail || b.hull) out += boat_line(b);
  for (const Body& b : scene.bodies)
    if (b.plate) out += plate_line(b);
  out += scene.ground ? ground_line(scene) : "- no ground: nothing to touch\n";
  for (const Contact& c : scene.contacts) {
    const std::string who =
        c.all_pairs ? "every pair of bodies"
        : c.ground  ? scene.bodies[c.body_a].name + " and the ground"
                    : scene.bodies[c.body_a].name + " and " + scene.bodies[c.body_b].name;
    out += fmt::format("- contact: {}, restitution {:g}, friction {}\n", who, c.restitution,
                       friction(c.friction_static, c.friction_kinetic));
  }
  // The bodies the case writes; those the grid or the waves make are folded below.
  const bool turned = std::any_of(scene.bodies.begin(), scene.bodies.end(), [](const Body& b) {
    return b.orientation.coeffs() != Quat::Identity().coeffs();
  });
  Table written = bodies_table(turned), generated = bodies_table(turned);
  for (std::size_t i = 0; i < scene.bodies.size(); ++i)
    (generated_body(scene, static_cast<int>(i)) ? generated : written)
        .rows.push_back(body_row(scene, scene.bodies[i], turned));
  if (!written.rows.empty()) out += "\n" + render_markdown(written);
  out += describe_interactions(scene);
  if (!generated.rows.empty())
    out +=
        fmt::format("\n<details><summary>The {} {} {} at the start</summary>\n\n{}\n</details>\n",
                    scene.grid ? "grid's" : "surface's", generated.rows.size(),
                    scene.grid ? "particles" : "points", render_markdown(generated));
  return out;
}

}  // namespace bb
