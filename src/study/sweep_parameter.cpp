#include "study/sweep_parameter.hpp"

#include <cmath>
#include <numbers>
#include <optional>
#include <type_traits>

#include "model/text.hpp"
#include "study/case_limits.hpp"
#include "study/vector_limits.hpp"
#include "study/wave_limits.hpp"

namespace bb {

std::vector<std::string> sweep_path_parts(const std::string& path) {
  std::vector<std::string> parts;
  std::string::size_type start = 0;
  while (true) {
    const std::string::size_type dot = path.find('.', start);
    parts.push_back(path.substr(start, dot - start));
    if (dot == std::string::npos) return parts;
    start = dot + 1;
  }
}

namespace {

constexpr double kDegree = std::numbers::pi / 180.0;

int component(const std::string& axis) {
  if (axis == "x") return 0;
  if (axis == "y") return 1;
  if (axis == "z") return 2;
  return -1;
}

/// The number of a [waves] that `name` names (null for none).
template <class W>
auto wave_field(W& waves, const std::string& name) -> decltype(&waves.amplitude) {
  if (name == "amplitude") return &waves.amplitude;
  if (name == "wavenumber") return &waves.wavenumber;
  if (name == "speed") return &waves.speed;
  return nullptr;
}

/// How many of Scene::springs, from the first, the [grid] made (they carry its line; the
/// loader adds them before any [[spring]]).
std::size_t grid_spring_count(const Scene& scene) {
  if (!scene.grid) return 0;
  std::size_t count = 0;
  while (count < scene.springs.size() && scene.springs[count].line == scene.grid->line) ++count;
  return count;
}

/// The index in Scene::springs of `[[spring]]` number `n` ("1" is the file's first; the
/// [grid]'s springs come before them), or -1.
template <class S>
int spring_table_index(S& scene, const std::string& n) {
  if (n.empty() || n.size() > 9 || n.find_first_not_of("0123456789") != std::string::npos ||
      n[0] == '0')
    return -1;
  const std::size_t first = grid_spring_count(scene);
  const std::size_t index = first + std::stoul(n) - 1;
  return index < scene.springs.size() ? static_cast<int>(index) : -1;
}

/// Where a path points: the number it names in `scene` (null when it names nothing).
template <class S>
std::conditional_t<std::is_const_v<S>, const double*, double*> target(
    S& scene, const std::vector<std::string>& p) {
  if (p[0] == "body" && (p.size() == 3 || p.size() == 4)) {
    const int i = scene.body_index(p[1]);
    if (i < 0) return nullptr;
    auto& b = scene.bodies[i];
    if (p.size() == 3) {
      if (p[2] == "mass") return &b.mass;
      if (p[2] == "radius") return &b.radius;
      if (p[2] == "drag_coefficient") return &b.drag_coefficient;
      if (p[2] == "magnus") return &b.magnus;
      return nullptr;
    }
    if (p[2] == "sail") {
      if (!b.sail) return nullptr;
      if (p[3] == "angle") return &b.sail->angle;
      if (p[3] == "area") return &b.sail->area;
      if (p[3] == "coefficient") return &b.sail->coefficient;
      if (p[3] == "heel_stiffness") return &b.sail->heel_stiffness;
      return nullptr;
    }
    if (p[2] == "plate") {
      if (!b.plate) return nullptr;
      if (p[3] == "k" && b.plate->law == PlateLaw::Course) return &b.plate->k;
      if (p[3] == "coefficient" && b.plate->law == PlateLaw::Quadratic)
        return &b.plate->coefficient;
      if (p[3] == "area") return &b.plate->area;
      return nullptr;
    }
    const int c = component(p[3]);
    if (c < 0) return nullptr;
    if (p[2] == "position") return &b.position[c];
    if (p[2] == "velocity") return &b.velocity[c];
    if (p[2] == "angular_velocity") return &b.angular_velocity[c];
    if (p[2] == "half_extents") return &b.half_extents[c];
    if (p[2] == "wind_force") return &b.wind_force[c];
    if (p[2] == "force") return &b.force[c];
    if (p[2] == "torque") return &b.torque[c];
    return nullptr;
  }
  if (p[0] == "ground" && p.size() == 2 && scene.ground) {
    if (p[1] == "restitution") return &scene.ground->restitution;
    if (p[1] == "friction_static") return &scene.ground->friction_static;
    if (p[1] == "friction_kinetic") return &scene.ground->friction_kinetic;
    return nullptr;
  }
  if (p[0] == "air" && scene.air) {
    if (p.size() == 2 && p[1] == "density") return &scene.air->density;
    if (p.size() == 3 && p[1] == "wind" && component(p[2]) >= 0)
      return &scene.air->wind[component(p[2])];
    return nullptr;
  }
  if (p[0] == "gravity" && p.size() == 2 && component(p[1]) >= 0)
    return &scene.gravity[component(p[1])];
  // A spring's constants; the grid's are one pair for all its springs.
  if (p[0] == "spring" && p.size() == 3) {
    const int i = spring_table_index(scene, p[1]);
    if (i < 0) return nullptr;
    if (p[2] == "stiffness") return &scene.springs[static_cast<std::size_t>(i)].stiffness;
    if (p[2] == "damping") return &scene.springs[static_cast<std::size_t>(i)].damping;
    return nullptr;
  }
  if (p[0] == "grid" && p.size() == 2 && scene.grid) {
    if (p[1] == "stiffness") return &scene.grid->stiffness;
    if (p[1] == "damping") return &scene.grid->damping;
    return nullptr;
  }
  if (p[0] == "waves" && p.size() == 2 && scene.waves) return wave_field(*scene.waves, p[1]);
  return nullptr;
}

/// The ground's "up" and the horizontal direction it tilts towards.
std::pair<Vec3, Vec3> tilt_frame(const Ground& g) {
  const Vec3 up = Vec3::UnitY();
  Vec3 across = g.normal - g.normal.dot(up) * up;
  if (across.norm() < 1e-12) across = Vec3::UnitX();
  return {up, across.normalized()};
}

/// The kind of vector a path's last part is a component of, if it is one.
std::optional<VectorKind> swept_vector_kind(const std::vector<std::string>& p) {
  if (component(p.back()) < 0) return std::nullopt;
  if (p[0] == "gravity") return VectorKind::Gravity;
  if (p[0] == "air") return VectorKind::Wind;
  if (p[0] != "body" || p.size() != 4) return std::nullopt;
  if (p[2] == "position") return VectorKind::Position;
  if (p[2] == "velocity") return VectorKind::Velocity;
  if (p[2] == "angular_velocity") return VectorKind::AngularVelocity;
  if (p[2] == "wind_force" || p[2] == "force") return VectorKind::Force;
  if (p[2] == "torque") return VectorKind::Torque;
  return std::nullopt;  // half_extents are sizes
}

/// The whole vector whose component a path names (see swept_vector_kind).
Vec3 swept_vector(const Scene& scene, const std::vector<std::string>& p) {
  if (p[0] == "gravity") return scene.gravity;
  if (p[0] == "air") return scene.air->wind;
  const Body& b = scene.bodies[scene.body_index(p[1])];
  if (p[2] == "position") return b.position;
  if (p[2] == "velocity") return b.velocity;
  if (p[2] == "angular_velocity") return b.angular_velocity;
  if (p[2] == "force") return b.force;
  if (p[2] == "torque") return b.torque;
  return b.wind_force;
}

const char* kKnownPaths =
    "body.<name>.mass|radius|drag_coefficient|magnus, "
    "body.<name>.position|velocity|angular_velocity|half_extents|wind_force|force|torque.x|y|z, "
    "body.<name>.sail.angle|area|coefficient|heel_stiffness, "
    "body.<name>.plate.k|coefficient|area (k with the course law, coefficient the quadratic), "
    "ground.restitution|friction_static|friction_kinetic|normal (an angle in degrees), "
    "air.density, air.wind.x|y|z, gravity.x|y|z, waves.amplitude|wavenumber|speed, "
    "spring.<n>.stiffness|damping (the n-th [[spring]], from 1), grid.stiffness|damping, "
    "dt (the step, report_dt)";

/// The step as a parameter: each point runs every backend at that step alone.
constexpr const char* kStep = "dt";

/// Why `value` cannot be the step, as the loader checks each of 'dt' ("" when it can);
/// `at` names the value.
std::string step_value_problem(const Scene& scene, const std::string& at, double value) {
  if (!(value > 0.0 && value <= scene.duration))
    return at + " must be greater than 0 and at most the duration, " +
           short_number(scene.duration) + " s";
  if (!is_whole_multiple(scene.sample / value))
    return at + " does not divide 'sample' (" + short_number(scene.sample) + " s) into whole steps";
  if (scene.duration / value > kMaxStepsPerRun)
    return at + " is " + short_number(scene.duration / value) +
           " steps over the duration; a run may take at most " + short_number(kMaxStepsPerRun);
  return "";
}

}  // namespace

std::string sweep_path_problem(const Scene& scene, const std::string& path) {
  if (path == kStep) return "";
  const std::vector<std::string> p = sweep_path_parts(path);
  const bool found = (p.size() == 2 && p[0] == "ground" && p[1] == "normal" && scene.ground) ||
                     target(scene, p) != nullptr;
  if (!found) {
    if (p[0] == "body" && p.size() >= 2 && scene.body_index(p[1]) < 0)
      return "'" + path + "' names no body '" + p[1] + "'";
    if (p[0] == "spring" && p.size() == 3 && spring_table_index(scene, p[1]) < 0)
      return "'" + path + "' names no [[spring]] number '" + p[1] + "' (they count from 1 in " +
             "the file's order)";
    if ((p[0] == "ground" && !scene.ground) || (p[0] == "air" && !scene.air) ||
        (p[0] == "waves" && !scene.waves) || (p[0] == "grid" && !scene.grid))
      return "'" + path + "' names the " + p[0] + ", and the case has no [" + p[0] + "]";
    return "'" + path + "' names nothing in the case; known: " + kKnownPaths;
  }
  if (p[0] == "body") {
    const Body& b = scene.bodies[scene.body_index(p[1])];
    if (b.fixed && p[2] != "position")
      return "'" + path + "': body '" + b.name + "' is fixed; only its position can be swept";
    if (p[2] == "radius" && b.shape != Shape::Sphere)
      return "'" + path + "': body '" + b.name + "' is not a sphere";
    if (p[2] == "torque" && b.shape == Shape::Point)
      return "'" + path + "': body '" + b.name + "' is a point, which does not turn";
    if ((p[2] == "half_extents" || p[2] == "wind_force") && b.shape != Shape::Box)
      return "'" + path + "': body '" + b.name + "' is not a box";
    if (scene.dims == 2 && p.size() == 4 && p[2] != "half_extents" && p[2] != "angular_velocity" &&
        p[2] != "torque" && p[3] == "z")
      return "'" + path + "': a 2D case keeps z at 0";
    if (scene.dims == 2 && (p[2] == "angular_velocity" || p[2] == "torque") && p[3] != "z")
      return "'" + path + "': a 2D body turns about z only";
  }
  if (scene.dims == 2 && p.back() == "z" && (p[0] == "gravity" || p[0] == "air"))
    return "'" + path + "': a 2D case keeps z at 0";
  return "";
}

std::string sweep_value_problem(const Scene& scene, const std::string& path, double value) {
  const std::vector<std::string> p = sweep_path_parts(path);
  const std::string& field = p[0] == "body" && p[2] != "sail" && p[2] != "plate" ? p[2] : p.back();
  const std::string at = "the value " + shortest_number(value) + " for '" + path + "'";
  if (!std::isfinite(value)) return at + " is not a finite number";
  if (path == kStep) return step_value_problem(scene, at, value);
  if (field == "mass" && !(value >= kLeastMass && value <= kMostMass))
    return at + " must be between " + short_number(kLeastMass) + " and " + short_number(kMostMass) +
           " kg";
  if ((field == "radius" || field == "half_extents") &&
      !(value >= kLeastSize && value <= kMostSize))
    return at + " must be between " + short_number(kLeastSize) + " and " + short_number(kMostSize) +
           " m";
  if ((field == "drag_coefficient" || field == "friction_static" || field == "friction_kinetic" ||
       field == "density") &&
      value < 0.0)
    return at + " must not be negative";
  if ((field == "area" || field == "coefficient" || field == "k") && value <= 0.0)
    return at + " must be greater than 0";
  // The loader's own bounds on a spring's constants ([[spring]] and [grid]).
  if ((p[0] == "spring" || p[0] == "grid") && field == "stiffness" &&
      !(value > 0.0 && value <= kMostSpringConstant))
    return at + " must be greater than 0 and at most " + short_number(kMostSpringConstant) + " N/m";
  if ((p[0] == "spring" || p[0] == "grid") && field == "damping" &&
      !(value >= 0.0 && value <= kMostSpringConstant))
    return at + " must be between 0 and " + short_number(kMostSpringConstant) + " N s/m";
  if (field == "heel_stiffness" && !(value > 0.0))
    return at +
           " must be greater than 0 (the boat heels by F_across / heel_stiffness, flat on "
           "the water as it falls to 0; an upright boat leaves the key out)";
  if (p[0] == "waves" && (field == "amplitude" || field == "speed") && value < 0.0)
    return at + " must not be negative";
  if (p[0] == "waves" && field == "wavenumber" && value <= 0.0)
    return at + " must be greater than 0";
  // The surface at this value, as the loader would check it in [waves].
  if (p[0] == "waves") {
    Waves w = *scene.waves;
    *wave_field(w, p[1]) = value;
    if (const WaveProblem problem = wave_problem(w); !problem.key.empty())
      return at + " " + problem.problem;
  }
  if (field == "angle" && (value < 0.0 || value > 90.0))
    return at + " is the sail's angle from the heading and must lie between 0 and 90 degrees";
  if (field == "restitution" && (value < 0.0 || value > 1.0))
    return at + " must be between 0 and 1";
  if (p[0] == "ground" && field == "normal" && std::abs(value) >= 90.0)
    return at + " is a tilt in degrees and must lie between -90 and 90";
  // Kinetic friction above static would push a body that stops off again.
  if (p[0] == "ground" && (field == "friction_static" || field == "friction_kinetic")) {
    const double mu_s = field == "friction_static" ? value : scene.ground->friction_static;
    const double mu_k = field == "friction_kinetic" ? value : scene.ground->friction_kinetic;
    if (mu_k > mu_s)
      return at + " puts friction_kinetic " + short_number(mu_k) + " above friction_static " +
             short_number(mu_s) + "; a body that stops would be pushed off again";
  }
  // A vector's component: the vector it makes must stay in its kind's range.
  if (const std::optional<VectorKind> kind = swept_vector_kind(p)) {
    Vec3 v = swept_vector(scene, p);
    v[component(p.back())] = value;
    if (const std::string problem = vector_limit_problem(*kind, v); !problem.empty())
      return at + " makes a vector that " + problem;
  }
  return "";
}

double sweep_parameter_value(const Scene& scene, const std::string& path) {
  if (path == kStep) return scene.report_dt;
  const std::vector<std::string> p = sweep_path_parts(path);
  if (p[0] == "ground" && p.size() == 2 && p[1] == "normal") {
    const auto [up, across] = tilt_frame(*scene.ground);
    return std::atan2(scene.ground->normal.dot(across), scene.ground->normal.dot(up)) / kDegree;
  }
  return *target(scene, p);
}

void set_sweep_parameter(Scene& scene, const std::string& path, double value) {
  if (path == kStep) {
    scene.report_dt = value;
    scene.dt = {value};
    return;
  }
  const std::vector<std::string> p = sweep_path_parts(path);
  if (!(p[0] == "ground" && p.size() == 2 && p[1] == "normal")) {
    *target(scene, p) = value;
    // The grid's constants are every one of its springs'.
    if (p[0] == "grid")
      for (std::size_t i = 0, n = grid_spring_count(scene); i < n; ++i) {
        Spring& spring = scene.springs[i];
        (p[1] == "stiffness" ? spring.stiffness : spring.damping) = value;
      }
    // A wave surface's points start where the formula puts them.
    if (p[0] == "waves")
      for (int i = 0; i < scene.waves->points; ++i)
        scene.bodies[static_cast<std::size_t>(scene.waves->first_body + i)] =
            wave_point(*scene.waves, i);
    return;
  }
  Ground& g = *scene.ground;
  // Named, not bound: the lambdas below use them (clang 14 cannot capture a structured binding).
  const std::pair<Vec3, Vec3> frame = tilt_frame(g);
  const Vec3 &up = frame.first, &across = frame.second;
  // The turn from the case's tilt to the swept one, written as a case is by hand: the
  // ground's normal from the angle's cosine and sine (unit length as the loader makes it),
  // each body's parts along `up` and `across` turned by the angle's difference, the part
  // across the tilt's plane left exactly as it is, and each orientation turned by the
  // loader's own angle-to-turn (a 2D body's `angle`). A quaternion turn from one normal to
  // the other left rounding along the new normal: a crate sliding on the slope then started
  // 1e-17 m/s off it, which a case written by hand does not.
  const double turn_degrees = value - sweep_parameter_value(scene, path);
  const double c = std::cos(turn_degrees * std::numbers::pi / 180.0);
  const double s = std::sin(turn_degrees * std::numbers::pi / 180.0);
  const auto turned_vector = [&](const Vec3& v) -> Vec3 {
    const double along = v.dot(across), height = v.dot(up);
    const Vec3 rest = v - along * across - height * up;
    return rest + (c * along + s * height) * across + (c * height - s * along) * up;
  };
  const auto turned = [&](const Vec3& x) -> Vec3 { return g.point + turned_vector(x - g.point); };
  const Quat turn =
      quat_from_axis_angle(across.cross(up).normalized(), -turn_degrees * std::numbers::pi / 180.0);
  for (Body& b : scene.bodies) {
    b.position = turned(b.position);
    b.velocity = turned_vector(b.velocity);
    b.angular_velocity = turned_vector(b.angular_velocity);
    b.orientation = turn * b.orientation;
  }
  for (Hinge& h : scene.hinges) {
    h.anchor = turned(h.anchor);
    h.axis = turned_vector(h.axis).normalized();
  }
  const double tilt = value * std::numbers::pi / 180.0;
  g.normal = (std::cos(tilt) * up + std::sin(tilt) * across).normalized();
}

std::vector<double> sweep_range(double from, double to, int count) {
  std::vector<double> values;
  for (int i = 0; i < count; ++i)
    values.push_back(i + 1 == count ? to : from + (to - from) * i / (count - 1));
  return values;
}

}  // namespace bb
