#include "report/scene_interactions.hpp"

#include <fmt/format.h>

#include <cmath>

#include "report/format.hpp"
#include "report/table.hpp"

namespace bb {

namespace {

/// Particles the grid made: its lattice's product of sizes.
int grid_particles(const Scene& scene) {
  const Grid& g = *scene.grid;
  return g.size[0] * g.size[1] * (scene.dims == 3 ? g.size[2] : 1);
}

bool made_by_grid(const Scene& scene, int index) {
  return scene.grid && index >= scene.grid->first_body &&
         index < scene.grid->first_body + grid_particles(scene);
}

/// The [grid] in one line: its lattice, its particles and the springs between them.
std::string grid_line(const Scene& scene) {
  const Grid& g = *scene.grid;
  std::string size = fmt::format("{} x {}", g.size[0], g.size[1]);
  if (scene.dims == 3) size += fmt::format(" x {}", g.size[2]);
  std::string out = fmt::format(
      "- a spring grid ([grid], \"Sproing\"): {} particles of {:g} kg, {:g} m apart from {}, "
      "rows laid {}, {}; each joined to its {} nearest neighbours by a spring of k = {:g} N/m "
      "and damping {:g} N s/m, its rest length the lattice distance ({:g} m along a row, "
      "{:g} m across a diagonal)",
      size, g.mass, g.spacing, format_vector(g.origin, scene.dims),
      g.rows == "up" ? "upwards (+y)" : "downwards (-y)",
      g.anchored == "top-row" ? "the row at the origin fixed" : "nothing fixed", g.neighbours,
      g.stiffness, g.damping, g.spacing, g.spacing * std::sqrt(2.0));
  if (g.jitter > 0.0)
    out += fmt::format("; each free particle moved by up to {:g} m (seed {})", g.jitter, g.seed);
  return out + "\n";
}

/// The [waves] in one line: the formula and its numbers.
std::string waves_line(const Waves& w) {
  return fmt::format(
      "- a Gerstner surface ([waves]): {} points at rest from x = {:g} to {:g} m at height "
      "{:g} m, each on a circle: x = x0 + A cos(w t + k x0), y = {:g} + A sin(w t + k x0), "
      "A = {:g} m, k = {:g} 1/m, w = {:g} rad/s; moved by the formula, not integrated\n",
      w.points, w.from, w.to, w.level, w.level, w.amplitude, w.wavenumber, w.speed);
}

/// A table with a bold label above it, or nothing when it has no rows.
std::string labelled(const std::string& label, const Table& t) {
  return t.rows.empty() ? std::string() : "\n" + label + "\n\n" + render_markdown(t);
}

Table springs_table(const Scene& scene) {
  Table t;
  t.headers = {"spring", "between", "k N/m", "damping N s/m", "rest length m"};
  t.right_aligned = {true, false, true, true, true};
  for (std::size_t i = 0; i < scene.springs.size(); ++i) {
    const Spring& s = scene.springs[i];
    // The grid's springs are its line's: one rule for all of them.
    if (made_by_grid(scene, s.body_a) || made_by_grid(scene, s.body_b)) continue;
    t.rows.push_back({std::to_string(i + 1),
                      scene.bodies[s.body_a].name + " and " + scene.bodies[s.body_b].name,
                      fmt::format("{:g}", s.stiffness), fmt::format("{:g}", s.damping),
                      fmt::format("{:g}", s.rest_length)});
  }
  return t;
}

Table hinges_table(const Scene& scene) {
  Table t;
  t.headers = {"body", "axis through m", "axis direction"};
  t.right_aligned = {false, false, false};
  for (const Hinge& h : scene.hinges)
    t.rows.push_back(
        {scene.bodies[h.body].name, format_vector(h.anchor, scene.dims), format_vector(h.axis, 3)});
  return t;
}

Table impulses_table(const Scene& scene) {
  Table t;
  t.headers = {"body", "at t s", "impulse N s", "acting at m"};
  t.right_aligned = {false, true, false, false};
  for (const Impulse& i : scene.impulses)
    t.rows.push_back({scene.bodies[i.body].name, fmt::format("{:g}", i.time),
                      format_vector(i.impulse, scene.dims),
                      i.point ? format_vector(*i.point, scene.dims) : std::string("its centre")});
  return t;
}

/// Every body with a constant push: a force, a torque or the wind's push on a face.
Table pushes_table(const Scene& scene) {
  Table t;
  t.headers = {"body", "force N", "torque N m", "wind on its face N"};
  t.right_aligned = {false, false, false, false};
  for (const Body& b : scene.bodies) {
    if (b.force.isZero() && b.torque.isZero() && b.wind_force.isZero()) continue;
    t.rows.push_back({b.name, format_vector(b.force, scene.dims), format_vector(b.torque, 3),
                      format_vector(b.wind_force, scene.dims)});
  }
  return t;
}

}  // namespace

bool generated_body(const Scene& scene, int index) {
  const bool wave_point = scene.waves && index >= scene.waves->first_body &&
                          index < scene.waves->first_body + scene.waves->points;
  return made_by_grid(scene, index) || wave_point;
}

std::string describe_interactions(const Scene& scene) {
  std::string out;
  if (scene.grid) out += grid_line(scene);
  if (scene.waves) out += waves_line(*scene.waves);
  out += labelled(
      "**Springs** (each pulls its two bodies together along the line between them by "
      "k (length - rest length) plus damping times their speed apart along it):",
      springs_table(scene));
  out += labelled("**Hinges** (each body turns about a fixed axis, its other motion held):",
                  hinges_table(scene));
  out += labelled(
      "**Impulses** (each changes its body's velocity by impulse / mass at once; "
      "off the centre also its spin by r x impulse):",
      impulses_table(scene));
  out += labelled(
      "**Constant pushes** (at the centre, in the world's frame; the wind's push "
      "is its part along the face's normal as the face turns):",
      pushes_table(scene));
  return out;
}

}  // namespace bb
