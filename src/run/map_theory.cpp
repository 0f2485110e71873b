#include "run/map_theory.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "course/tunnelling_theory.hpp"
#include "model/contact_pairs.hpp"
#include "run/stability.hpp"
#include "run/sweep_runner.hpp"
#include "study/backend_names.hpp"

namespace bb {

namespace {

/// Seed section 6, Coulomb's law: a body at rest on the tilted ground holds while the slope's
/// pull m g sin(theta) is at most mu_s m g cos(theta), up to atan(mu_s) (degrees, as the
/// "ground.normal" axis tilts). The law, not a method: every backend's map has the line. It
/// covers one moving body at rest on a ground, under gravity alone.
std::optional<double> coulomb_hold_tilt(const Scene& point, const std::string&) {
  if (!point.ground || point.gravity.norm() == 0.0 || point.air || point.water ||
      !point.springs.empty() || !point.impulses.empty() || !point.hinges.empty())
    return std::nullopt;
  std::optional<ContactPair> pair;
  for (std::size_t i = 0; i < point.bodies.size(); ++i) {
    const Body& b = point.bodies[i];
    if (b.fixed) continue;
    if (pair || b.velocity.norm() > 0.0 || b.angular_velocity.norm() > 0.0) return std::nullopt;
    pair = ground_pair(point, static_cast<int>(i));
  }
  if (!pair) return std::nullopt;
  return std::atan(pair->friction_static) * 180.0 / std::numbers::pi;
}

/// Seed section 4: the course's end-of-step collision test surely turns a ball back from a
/// thin fixed box only below (h + r) / v (course/tunnelling_theory.hpp), for a course variant
/// whose rule moves the ball out of what it hit (clamp, mirror; reflect leaves it inside).
std::optional<double> course_catch_step(const Scene& point, const std::string& backend) {
  for (const CourseVariant& v : course_variants(point))
    if (v.name == backend && v.ground != "reflect") return surely_turned_back_step(point);
  return std::nullopt;
}

}  // namespace

const std::vector<MapTheory>& map_theories() {
  static const std::vector<MapTheory> theories = {
      // Seed section 7: the course integrator's largest stable step (stability_theory.hpp),
      // as the stability search's theory column states it.
      {"dt", "theory's largest stable step",
       "the course theory's largest stable step for the backend's integrator (stable on the "
       "side of the smaller steps)",
       "Where one axis is the step and the course text's theory covers a backend's integrator, "
       "the dashed line is the theory's largest stable step at each value of the other (the "
       "stability search's theory column, computed at that point). A run is judged over the "
       "case's duration only: growth too slow to show in that time (explicit Euler at the "
       "smallest steps) is ok on the map though the theory calls it unstable.",
       "the step (dt), for a course integrator on a scene the course's stability theory "
       "describes (springs, no contacts)",
       [](const Scene& point, const std::string& backend) { return theory_for(point, backend); }},
      {"ground.normal", "Coulomb's steepest holding tilt (degrees)",
       "Coulomb's law: the block holds on tilts up to atan(mu_s), slides beyond (below the line "
       "it should hold)",
       "The dashed line is Coulomb's law (seed section 6) at each static friction: a block at "
       "rest holds while m g sin(tilt) <= mu_s m g cos(tilt), on every tilt up to atan(mu_s), "
       "and slides beyond; the same line on every backend's map, since it is the law and not a "
       "method.",
       "the ground's tilt (ground.normal), for every backend, on one body set at rest on the "
       "ground under gravity alone",
       coulomb_hold_tilt},
      {"dt", "step the course's test surely turns the ball back below",
       "(panel's half thickness + ball's radius) / speed: below it a step surely ends with the "
       "ball in the panel's near half, which turns it back",
       "On a course variant's map the dashed line is (h + r) / v, h the panel's half thickness, "
       "r the ball's radius and v its speed: the course tests for an overlap only at the end of "
       "each step and turns a ball out through the face nearest its centre, so it turns back "
       "for certain only where steps v dt apart must end inside the panel's near half, v dt < "
       "h + r (half of the panel's thickness and the ball's diameter, not all of it). Past the "
       "line whether a step lands there, in the far half (out through the far face) or in "
       "neither (never seen) depends on where the steps happen to fall.",
       "the step (dt), for a course variant whose collision rule moves a ball out of a thin "
       "fixed box it flies at (clamp, mirror)",
       course_catch_step},
  };
  return theories;
}

bool bounds_first_sweep(const Scene& scene, const MapTheory& theory) {
  return scene.sweep->parameter == theory.bounded;
}

namespace {

/// `theory`'s bound for `backend` at each value of the axis it does not bound, ascending;
/// empty where the map has no axis it bounds or it does not cover every value.
std::vector<BoundaryPoint> bounds(const Scene& scene, const MapTheory& theory,
                                  const std::string& backend) {
  if (!scene.sweep || !scene.second_sweep) return {};
  const bool first = bounds_first_sweep(scene, theory);
  if (!first && scene.second_sweep->parameter != theory.bounded) return {};
  std::vector<double> others = first ? scene.second_sweep->values : scene.sweep->values;
  std::sort(others.begin(), others.end());
  // The bounded parameter's value at a point does not move its bound: any one will do.
  const double any = first ? scene.sweep->values.front() : scene.second_sweep->values.front();
  std::vector<BoundaryPoint> out;
  for (double value : others) {
    const Scene point =
        first ? map_point_scene(scene, any, value) : map_point_scene(scene, value, any);
    const std::optional<double> limit = theory.bound(point, backend);
    if (!limit) return {};
    out.push_back({value, *limit});
  }
  return out;
}

}  // namespace

const MapTheory* map_theory(const Scene& scene, const std::string& backend) {
  for (const MapTheory& theory : map_theories())
    if (!bounds(scene, theory, backend).empty()) return &theory;
  return nullptr;
}

std::vector<BoundaryPoint> map_boundary(const Scene& scene, const std::string& backend) {
  const MapTheory* theory = map_theory(scene, backend);
  return theory ? bounds(scene, *theory, backend) : std::vector<BoundaryPoint>{};
}

std::string map_theories_cover() {
  std::string out;
  for (const MapTheory& theory : map_theories()) out += (out.empty() ? "" : "; ") + theory.covers;
  return out;
}

}  // namespace bb
