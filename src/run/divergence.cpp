#include "run/divergence.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

#include "model/text.hpp"

namespace bb {

DivergenceBounds divergence_bounds(const Scene& scene) {
  return divergence_bounds(scene, scene.duration, kBlowUpEnergy);
}

DivergenceBounds divergence_bounds(const Scene& scene, double duration, double factor) {
  DivergenceBounds bounds;
  bounds.scale = energy_scale(scene, duration);
  bounds.factor = factor;
  bounds.energy = factor * bounds.scale.total();
  const double root = std::sqrt(factor);
  const std::vector<double> fastest = speed_bounds(scene, bounds.scale, duration);
  for (std::size_t i = 0; i < scene.bodies.size(); ++i) {
    const Body& b = scene.bodies[i];
    bounds.speed.push_back(root * fastest[i]);
    bounds.travel.push_back(root * (fastest[i] * duration + b.radius + b.half_extents.norm()));
  }
  return bounds;
}

std::optional<Beyond> beyond_reference(const Scene& scene, const Trajectory& run,
                                       const Trajectory& reference) {
  // The box around every moving body of the reference at every sample, its surface included.
  Eigen::AlignedBox3d box;
  double reach = 0.0;
  for (std::size_t i = 0; i < scene.bodies.size(); ++i) {
    const Body& b = scene.bodies[i];
    if (b.fixed) continue;
    reach = std::max(reach, b.radius + b.half_extents.norm());
    for (const State& s : reference.states) box.extend(s[i].position);
  }
  if (box.isEmpty()) return std::nullopt;
  const double size = std::max(box.diagonal().norm(), 2.0 * reach);
  if (!(size > 0.0)) return std::nullopt;
  const double limit = kBeyondReference * size;
  for (std::size_t j = 0; j < run.states.size(); ++j)
    for (std::size_t i = 0; i < scene.bodies.size(); ++i) {
      if (scene.bodies[i].fixed) continue;
      const double outside = box.exteriorDistance(run.states[j][i].position);
      if (outside > limit)
        return Beyond{run.times[j],
                      "body '" + scene.bodies[i].name + "' went " + significant_digits(outside, 3) +
                          " m outside everywhere the reference's bodies go (a box " +
                          significant_digits(size, 3) + " m across), more than " +
                          significant_digits(kBeyondReference, 3) + " times its size"};
    }
  return std::nullopt;
}

std::optional<std::string> divergence(const Scene& scene, const DivergenceBounds& bounds,
                                      const State& state, double initial_energy, double energy) {
  const double root = std::sqrt(bounds.factor);
  for (std::size_t i = 0; i < state.size(); ++i) {
    const BodyState& s = state[i];
    const Body& b = scene.bodies[i];
    if (!s.position.allFinite() || !s.velocity.allFinite() || !s.angular_velocity.allFinite())
      return "body '" + b.name + "' has a NaN or infinite position or velocity";
    if (b.fixed) continue;
    if (const double speed = s.velocity.norm(); speed > bounds.speed[i])
      return "body '" + b.name + "' moves at " + significant_digits(speed, 3) + " m/s, more than " +
             significant_digits(root, 3) + " times the " +
             significant_digits(bounds.speed[i] / root, 3) +
             " m/s the scene can give it (its start, free fall over the run, and all the "
             "energy the scene can put into motion, " +
             significant_digits(bounds.scale.total(), 3) + " J, given to it alone)";
    if (const double moved = (s.position - b.position).norm(); moved > bounds.travel[i])
      return "body '" + b.name + "' moved " + significant_digits(moved, 3) + " m from its start, " +
             "more than " + significant_digits(root, 3) + " times the " +
             significant_digits(bounds.travel[i] / root, 3) +
             " m the fastest the scene can move it allows";
  }
  if (const double rise = energy - initial_energy; rise > bounds.energy)
    return "energy rose by " + significant_digits(rise, 3) + " J, more than " +
           significant_digits(bounds.factor, 3) + " times the " + bounds.scale.describe() +
           " the scene can put into motion";
  return std::nullopt;
}

}  // namespace bb
