// [[body]] tables of a case file.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <utility>

#include "model/contact_pairs.hpp"
#include "model/rest_on.hpp"
#include "model/text.hpp"
#include "study/load_case.hpp"
#include "study/load_parts.hpp"
#include "study/vector_limits.hpp"

namespace bb::load {

namespace {

Shape read_shape(TomlReader& r) {
  const std::string shape = r.string_or("shape", "sphere");
  if (shape == "sphere") return Shape::Sphere;
  if (shape == "box") return Shape::Box;
  if (shape == "point") return Shape::Point;
  r.fail(r.line_of("shape"), "'shape' must be sphere, box or point, not '" + shape + "'");
}

/// Keys that belong to one shape only, rejected with a clear word on the others.
void reject_foreign_key(TomlReader& r, const std::string& key, const std::string& owner) {
  if (r.has(key))
    r.fail(r.line_of(key),
           "'" + key + "' belongs to a " + owner + "; " + r.where() + " is not one");
}

void read_geometry(TomlReader& r, Body& b) {
  if (b.shape == Shape::Sphere) {
    b.radius = r.number("radius");
    require_range(r, "radius", b.radius, kLeastSize, kMostSize);
  } else {
    reject_foreign_key(r, "radius", "sphere");
  }
  if (b.shape == Shape::Box) {
    b.half_extents = r.vec3("half_extents");
    if (!(b.half_extents.minCoeff() >= kLeastSize && b.half_extents.maxCoeff() <= kMostSize))
      r.fail(r.line_of("half_extents"), "every 'half_extents' in " + r.where() +
                                            " must be between " + short_number(kLeastSize) +
                                            " and " + short_number(kMostSize) + " m");
  } else {
    reject_foreign_key(r, "half_extents", "box");
  }
  if (b.shape != Shape::Sphere) reject_foreign_key(r, "shell", "sphere");
  b.shell = r.boolean_or("shell", false);
}

void read_orientation(TomlReader& r, const Scene& scene, Body& b) {
  if (scene.dims == 2) {
    if (r.has("orientation"))
      r.fail(r.line_of("orientation"),
             "'orientation' is for 3D cases; a 2D body uses 'angle' (degrees about z)");
    const double degrees = r.number_or("angle", 0.0);
    b.orientation = quat_from_axis_angle({0, 0, 1}, degrees * std::numbers::pi / 180.0);
  } else {
    if (r.has("angle"))
      r.fail(r.line_of("angle"),
             "'angle' is for 2D cases; a 3D body uses 'orientation' = [w, x, y, z]");
    if (r.has("orientation")) {
      const std::vector<double> q = r.numbers("orientation", 4);
      const double n = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
      if (n < 1e-12) r.fail(r.line_of("orientation"), "'orientation' must not be all zeros");
      b.orientation = Quat(q[0], q[1], q[2], q[3]).normalized();
    }
  }
  b.angular_velocity = r.vec3_or("angular_velocity", {});
  if (scene.dims == 2 && (b.angular_velocity.x() != 0.0 || b.angular_velocity.y() != 0.0))
    r.fail(r.line_of("angular_velocity"),
           "a 2D body spins about z only: 'angular_velocity' must be [0, 0, wz]");
  require_vector_range(r, "angular_velocity", b.angular_velocity, VectorKind::AngularVelocity);
}

/// A fixed body never moves: a velocity or a spin given to it would be read one way by one
/// backend and another by the next (Box2D sends such a body off, the others hold it).
void refuse_motion_of_fixed(const TomlReader& r, const Body& b) {
  if (!b.fixed) return;
  for (const auto& [key, v] : {std::pair<std::string, Vec3>{"velocity", b.velocity},
                               {"angular_velocity", b.angular_velocity}})
    if (!v.isZero(0.0))
      r.fail(r.line_of(key), r.where() + " is fixed (it never moves): its '" + key +
                                 "' must be zero, or leave 'fixed' out");
}

void read_air_coefficients(TomlReader& r, const Scene& scene, Body& b) {
  b.drag_coefficient = r.number_or("drag_coefficient", 0.0);
  require_range(r, "drag_coefficient", b.drag_coefficient, 0.0, 0.0);
  b.magnus = r.number_or("magnus", 0.0);
  if (b.drag_coefficient > 0.0 && b.shape != Shape::Sphere)
    r.fail(r.line_of("drag_coefficient"),
           "drag needs a frontal area: only a sphere has one (A = pi r^2)");
  if (b.magnus != 0.0 && b.shape == Shape::Point)
    r.fail(r.line_of("magnus"), "a point does not spin, so it feels no Magnus force");
  b.wind_force = r.vec3_or("wind_force", {});
  require_planar(r, scene, "wind_force", b.wind_force);
  require_vector_range(r, "wind_force", b.wind_force, VectorKind::Force);
  if (b.wind_force.norm() > 0.0 && b.shape != Shape::Box)
    r.fail(r.line_of("wind_force"),
           "'wind_force' pushes a box's broad face (a panel, a wall); body '" + b.name +
               "' is not a box");
  if ((b.drag_coefficient > 0.0 || b.magnus != 0.0) && !scene.air)
    r.fail(r.line_of(b.drag_coefficient > 0.0 ? "drag_coefficient" : "magnus"),
           r.where() + " has air coefficients but the case has no [air] section");
}

/// A constant force and torque ([[body]] `force`, `torque`, world frame).
void read_applied_load(TomlReader& r, const Scene& scene, Body& b) {
  b.force = r.vec3_or("force", {});
  require_planar(r, scene, "force", b.force);
  require_vector_range(r, "force", b.force, VectorKind::Force);
  b.torque = r.vec3_or("torque", {});
  if (scene.dims == 2 && (b.torque.x() != 0.0 || b.torque.y() != 0.0))
    r.fail(r.line_of("torque"), "a 2D body turns about z only: 'torque' must be [0, 0, tz]");
  require_vector_range(r, "torque", b.torque, VectorKind::Torque);
  if (!b.torque.isZero(0.0) && b.shape == Shape::Point)
    r.fail(r.line_of("torque"),
           "a point does not turn, so a torque on '" + b.name + "' has nothing to act on");
  for (const char* key : {"force", "torque"})
    if (b.fixed && r.has(key) && !(key[0] == 'f' ? b.force : b.torque).isZero(0.0))
      r.fail(r.line_of(key), r.where() + " is fixed (it never moves): a '" + key +
                                 "' on it moves nothing; leave it out");
}

/// What every boat needs: a 2D case seen from above, with the water holding it up.
void require_boat_world(TomlReader& r, const Scene& scene, const std::string& key) {
  if (scene.dims != 2)
    r.fail(r.line_of(key), "a boat sails on the water seen from above: '" + key +
                               "' needs a 2D case (the x-y plane is the water)");
  if (!scene.gravity.isZero(0.0))
    r.fail(r.line_of(key), "the water holds a boat up: a case with a '" + key +
                               "' sets gravity = [0.0, 0.0, 0.0] (the x-y plane is the water "
                               "seen from above)");
  if (r.has("drag_coefficient") || r.has("magnus") || r.has("wind_force"))
    r.fail(r.line_of(key),
           "a boat feels the wind through its sail only: leave "
           "'drag_coefficient', 'magnus' and 'wind_force' out of " +
               r.where());
}

/// [body.sail] (seed section 9): area, coefficient, angle from the heading, heel stiffness.
void read_sail(TomlReader& r, const Scene& scene, Body& b) {
  const toml::table* t = r.table("sail");
  if (t == nullptr) return;
  require_boat_world(r, scene, "sail");
  if (!scene.air) r.fail(r.line_of("sail"), "a sail needs the wind: the case has no [air] section");
  TomlReader s = sub_reader(r, *t, "[body.sail]");
  Sail sail;
  sail.area = s.number("area");
  require_range(s, "area", sail.area, 0.0, 0.0, false);
  sail.coefficient = s.number_or("coefficient", sail.coefficient);
  require_range(s, "coefficient", sail.coefficient, 0.0, 0.0, false);
  sail.angle = s.number("angle");
  require_range(s, "angle", sail.angle, 0.0, 90.0);
  // Heel tends to flat on the water as the stiffness falls to 0: an upright boat (infinitely
  // stiff) leaves the key out, so that 0 cannot mean upright beside 1e-300 meaning flat.
  if (s.has("heel_stiffness")) {
    sail.heel_stiffness = s.number("heel_stiffness");
    if (!(sail.heel_stiffness > 0.0))
      s.fail(s.line_of("heel_stiffness"),
             "'heel_stiffness' in " + s.where() + " must be greater than 0, not " +
                 show(sail.heel_stiffness) +
                 ": the boat heels by F_across / heel_stiffness, flat on the water as it falls "
                 "to 0; leave the key out for a boat that stays upright");
  }
  s.finish();
  b.sail = sail;
}

/// [body.plate] (seed section 8, "Wind"): a box's broad face pushed along its normal by the
/// wind relative to it, by the text's linear law (k) or the sail's quadratic one.
void read_plate(TomlReader& r, const Scene& scene, Body& b) {
  const toml::table* t = r.table("plate");
  if (t == nullptr) return;
  if (b.shape != Shape::Box)
    r.fail(r.line_of("plate"), "a plate is a box's broad face: '" + b.name + "' is not a box");
  if (!scene.air)
    r.fail(r.line_of("plate"), "a plate is pushed by the wind: the case has no [air] section");
  if (b.fixed) r.fail(r.line_of("plate"), r.where() + " is fixed: the wind moves nothing");
  if (b.sail) r.fail(r.line_of("plate"), "a boat feels the wind through its sail only");
  TomlReader s = sub_reader(r, *t, "[body.plate]");
  Plate plate;
  const std::string law = s.string("law");
  if (law == "course") {
    plate.law = PlateLaw::Course;
    plate.k = s.number("k");
    require_range(s, "k", plate.k, 0.0, 0.0, false);
    if (s.has("coefficient"))
      s.fail(s.line_of("coefficient"), "the course law takes 'k', not 'coefficient'");
  } else if (law == "quadratic") {
    plate.law = PlateLaw::Quadratic;
    plate.coefficient = s.number_or("coefficient", plate.coefficient);
    require_range(s, "coefficient", plate.coefficient, 0.0, 0.0, false);
    if (s.has("k")) s.fail(s.line_of("k"), "the quadratic law takes 'coefficient', not 'k'");
  } else {
    s.fail(s.line_of("law"), "law is \"course\" or \"quadratic\", not \"" + law + "\"");
  }
  // The broad face: the two largest half extents, 2 a by 2 b.
  Vec3 h = b.half_extents;
  std::sort(h.data(), h.data() + 3);
  plate.area = s.number_or("area", 4.0 * h[1] * h[2]);
  require_range(s, "area", plate.area, 0.0, 0.0, false);
  s.finish();
  b.plate = plate;
}

/// [body.hull]: drag areas ahead, astern and across, or no drift at all.
void read_hull(TomlReader& r, const Scene& scene, Body& b) {
  const toml::table* t = r.table("hull");
  if (t == nullptr) return;
  require_boat_world(r, scene, "hull");
  if (!scene.water)
    r.fail(r.line_of("hull"), "a hull needs the water: the case has no [water] section");
  TomlReader s = sub_reader(r, *t, "[body.hull]");
  Hull hull;
  hull.forward = s.number("forward");
  require_range(s, "forward", hull.forward, 0.0, 0.0);
  hull.backward = s.number_or("backward", hull.forward);
  require_range(s, "backward", hull.backward, 0.0, 0.0);
  hull.no_drift = s.boolean_or("no_drift", false);
  if (hull.no_drift && s.has("sideways"))
    s.fail(s.line_of("sideways"),
           "'no_drift' makes the sideways drag infinite: leave 'sideways' out");
  hull.sideways = hull.no_drift ? 0.0 : s.number("sideways");
  require_range(s, "sideways", hull.sideways, 0.0, 0.0);
  s.finish();
  // With no drift the boat starts as it goes on: along its heading.
  const Vec3 across = b.orientation * Vec3(0.0, 1.0, 0.0);
  if (hull.no_drift && std::abs(b.velocity.dot(across)) > 1e-9 * b.velocity.norm())
    r.fail(r.line_of("velocity"), r.where() +
                                      " has no drift: its 'velocity' must point along "
                                      "its heading (the body's x axis at 'angle')");
  b.hull = hull;
}

/// `rest_on`: "ground" places the body on the ground (rest_on.hpp); another body's name is
/// returned, to place it once every body is read. Without it, a moving box that starts a
/// hair's breadth off the ground is told where it is and what places it.
std::optional<std::string> read_rest_on(TomlReader& r, const Scene& scene, Body& b) {
  if (!r.has("rest_on")) {
    if (!scene.ground || b.fixed) return std::nullopt;
    if (const std::string miss = near_ground_miss(b, *scene.ground); !miss.empty())
      r.fail(r.line_of("position"),
             "body '" + b.name + "' " + miss + ": set rest_on = \"ground\" to place it on it");
    return std::nullopt;
  }
  const std::string on = r.string("rest_on");
  if (on != "ground" && scene.gravity.isZero(0.0))
    r.fail(r.line_of("rest_on"),
           r.where() + " rests on '" + on + "' along gravity, and the case has none");
  if (on == "ground" && !scene.ground)
    r.fail(r.line_of("rest_on"), r.where() + " rests on the ground, and the case has no [ground]");
  // A box is turned to what it rests on: a turn of its own would be overruled.
  for (const char* key : {"angle", "orientation"})
    if (b.shape == Shape::Box && r.has(key))
      r.fail(r.line_of(key), "rest_on turns box '" + b.name + "' to " +
                                 (on == "ground" ? "the ground" : "'" + on + "'") +
                                 " (its y axis along the normal): leave '" + key +
                                 "' out (to stand it on another face, swap its half_extents)");
  if (on != "ground") return on;
  place_on_ground(b, *scene.ground);
  require_vector_range(r, "position", b.position, VectorKind::Position);
  return std::nullopt;
}

/// Places the resting bodies, each after the body under it (a stack is placed from the
/// bottom), refusing an unknown body, a ring of bodies resting on each other, and a body
/// that cannot rest where it is (place_on_body's reasons).
void place_resting(const TomlReader& root, Scene& scene, const std::vector<Resting>& resting) {
  std::vector<int> state(scene.bodies.size(), 0);  // 0 to place, 1 placing, 2 placed
  std::vector<const Resting*> of(scene.bodies.size(), nullptr);
  for (const Resting& r : resting) of[static_cast<std::size_t>(r.body)] = &r;
  const Vec3 up = -scene.gravity.normalized();
  const auto place = [&](const auto& self, const Resting& r) -> void {
    const auto index = static_cast<std::size_t>(r.body);
    if (state[index] == 2) return;
    Body& body = scene.bodies[index];
    if (state[index] == 1)
      root.fail(r.line, "body '" + body.name + "' rests, through rest_on, on itself");
    state[index] = 1;
    const int below = scene.body_index(r.on);
    if (below < 0) root.fail(r.line, "'rest_on' \"" + r.on + "\" is neither \"ground\" nor a body");
    if (const Resting* under = of[static_cast<std::size_t>(below)]) self(self, *under);
    if (const std::string problem = place_on_body(body, scene.bodies[below], up); !problem.empty())
      root.fail(r.line, "body '" + body.name + "' cannot rest on '" + r.on + "': " + problem);
    if (const std::string problem = vector_limit_problem(VectorKind::Position, body.position);
        !problem.empty())
      root.fail(r.line, "body '" + body.name + "' resting on '" + r.on + "' has a position that " +
                            problem);
    refuse_ground_overlap(root, scene, body, r.line);
    state[index] = 2;
  };
  for (const Resting& r : resting) place(place, r);
}

}  // namespace

std::vector<Resting> read_bodies(TomlReader& root, Scene& scene) {
  std::vector<Resting> resting;
  for (const toml::table* t : root.tables("body")) {
    TomlReader r = sub_reader(root, *t, "[[body]]");
    Body b;
    b.line = r.line();
    b.name = r.string("name");
    if (character_count(b.name) > kMaxNameLength)
      r.fail(r.line_of("name"), "a body name is " + std::to_string(character_count(b.name)) +
                                    " characters long; it may be at most " +
                                    std::to_string(kMaxNameLength));
    if (!is_name(b.name, true, ".-"))
      r.fail(r.line_of("name"),
             "a body name uses only letters, digits, '_', '.' and '-', not '" + b.name + "'");
    r.rename("[[body]] '" + b.name + "'");
    b.shape = read_shape(r);
    read_geometry(r, b);
    b.fixed = r.boolean_or("fixed", false);
    b.mass = b.fixed ? r.number_or("mass", 0.0) : r.number("mass");
    if (!b.fixed || b.mass != 0.0) require_range(r, "mass", b.mass, kLeastMass, kMostMass);
    b.position = r.vec3_or("position", {});
    require_planar(r, scene, "position", b.position);
    require_vector_range(r, "position", b.position, VectorKind::Position);
    b.velocity = r.vec3_or("velocity", {});
    require_planar(r, scene, "velocity", b.velocity);
    require_vector_range(r, "velocity", b.velocity, VectorKind::Velocity);
    read_orientation(r, scene, b);
    refuse_motion_of_fixed(r, b);
    const std::optional<std::string> on = read_rest_on(r, scene, b);
    if (on) resting.push_back({static_cast<int>(scene.bodies.size()), *on, r.line_of("rest_on")});
    read_air_coefficients(r, scene, b);
    read_applied_load(r, scene, b);
    read_sail(r, scene, b);
    read_hull(r, scene, b);
    read_plate(r, scene, b);
    if (!on) refuse_ground_overlap(r, scene, b, r.line_of("position"));
    r.finish();
    scene.bodies.push_back(b);
  }
  place_resting(root, scene, resting);
  return resting;
}

void require_resting_contacts(const TomlReader& root, const Scene& scene,
                              const std::vector<Resting>& resting) {
  if (resting.empty()) return;
  const std::vector<ContactPair> pairs = contact_pairs(scene);
  for (const Resting& r : resting) {
    const int below = scene.body_index(r.on);
    const bool touch = std::any_of(pairs.begin(), pairs.end(), [&](const ContactPair& p) {
      return (p.a == r.body && p.b == below) || (p.a == below && p.b == r.body);
    });
    const Body& body = scene.bodies[static_cast<std::size_t>(r.body)];
    if (!touch && !(body.fixed && scene.bodies[static_cast<std::size_t>(below)].fixed))
      root.fail(r.line, "body '" + body.name + "' rests on '" + r.on +
                            "', and the two do not touch: add a [[contact]] with bodies = [\"" +
                            body.name + "\", \"" + r.on + "\"] (or [\"*\"]), or it falls through");
  }
}

}  // namespace bb::load
