// The parameter a [[sweep]] varies: a path into the case ("body.ball.position.y",
// "ground.restitution", "ground.normal" as an angle, "spring.1.stiffness", "grid.damping", the
// step "dt", ...)
// read from and written into a loaded Scene, so every point of a sweep is the same case with one
// number changed.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "study/scene.hpp"

namespace bb {

/// A path split at its dots: "body.ball.position.y" is body, ball, position, y.
std::vector<std::string> sweep_path_parts(const std::string& path);

/// Why `path` names nothing in `scene` (with the paths it could name), or "" when it does.
std::string sweep_path_problem(const Scene& scene, const std::string& path);

/// Why `value` cannot stand at `path` (a negative mass, a restitution above 1, a kinetic
/// friction above the static one, a vector outside its range, ...), or "". Overlaps of the
/// swept body are the loader's to find (they need the case's contacts).
/// `path` must name something (sweep_path_problem is "").
std::string sweep_value_problem(const Scene& scene, const std::string& path, double value);

/// The case's own value at `path`: for "ground.normal" its tilt from level in degrees.
double sweep_parameter_value(const Scene& scene, const std::string& path);

/// `scene` with `value` at `path`; "dt" makes `value` the case's only step and report_dt.
/// "ground.normal" tilts the ground by `value` degrees from level, in the direction the case tilts
/// it (towards +x when the case's ground is level), about the ground's point, and turns the bodies
/// and hinges with it, as a table tilted with what stands on it; gravity, the air and the wind
/// stay. From a level case the scene is, to the bit, the case written by hand at that tilt (normal
/// [sin, cos], positions and velocities turned by cos and sin of degrees pi / 180, each 2D `angle`
/// less the tilt).
void set_sweep_parameter(Scene& scene, const std::string& path, double value);

/// The values `[from, to, count]` of a range: count points, evenly spaced, both ends in.
std::vector<double> sweep_range(double from, double to, int count);

}  // namespace bb
