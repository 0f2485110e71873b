// time_above (s): how long the body's centre is above a level over the run: its height along
// -gravity (as final_height reads it) above the [[observe]]'s `level`. The level's crossings
// are the events it watches (a CrossingFn): the reference locates each exactly, a stepped
// backend places each on the line between the two steps around it; the time above is summed
// between them. This file and one row in observable_registry.cpp.
#include <string>

#include "observe/observable_measure.hpp"

namespace bb {

double height_above_level(const World& world, const Observe& observe, const BodyState& body) {
  const double g = world.gravity.norm();
  const Vec3 up = g > 0.0 ? Vec3(-world.gravity / g) : Vec3::UnitY();
  return body.position.dot(up) - observe.level.value_or(0.0);
}

ObservableValue measure_time_above(const Scene& scene, const Observe& observe,
                                   const Trajectory& trajectory, const EventTrace*) {
  if (scene.gravity.norm() <= 0.0) return {std::nullopt, "does not apply: the case has no gravity"};
  const auto found = trajectory.events.crossings.find(observe.name);
  if (found == trajectory.events.crossings.end())
    return {std::nullopt, "the run has no crossings of the level watched"};
  const std::vector<Crossing>& crossings = found->second;
  // Above before the first crossing when it goes down through the level; with none, the
  // body is on the side it ends on throughout.
  const double end = trajectory.times.back();
  bool above = crossings.empty() ? height_above_level(scene, observe,
                                                      trajectory.states.back()[observe.body]) > 0.0
                                 : !crossings.front().rising;
  double since = 0.0, total = 0.0;
  for (const Crossing& c : crossings) {
    if (above) total += c.time - since;
    above = c.rising, since = c.time;
  }
  if (above) total += end - since;
  return {total, ""};
}

}  // namespace bb
