#include "scene/rest_on.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "scene/initial_overlap.hpp"
#include "scene/text.hpp"

namespace bb {

namespace {

/// How far `body` reaches from its centre along the unit `n`.
double reach_along(const Body& body, const Vec3& n) {
  if (body.shape == Shape::Sphere) return body.radius;
  if (body.shape == Shape::Point) return 0.0;
  Ground through_centre;
  through_centre.point = body.position;
  through_centre.normal = n;
  return ground_depth(body, through_centre);
}

}  // namespace

void place_on_ground(Body& body, const Ground& ground) {
  const Vec3& n = ground.normal;
  double reach = body.shape == Shape::Sphere ? body.radius : 0.0;
  if (body.shape == Shape::Box) {
    body.orientation = Quat::FromTwoVectors(Vec3::UnitY(), n);
    reach = body.half_extents.y();
  }
  const Vec3 foot = body.position - (body.position - ground.point).dot(n) * n;
  body.position = foot + reach * n;
}

std::string near_ground_miss(const Body& body, const Ground& ground) {
  const double size = reach_along(body, ground.normal);
  if (size <= 0.0) return "";
  const double depth = ground_depth(body, ground);
  const double gap = std::abs(depth);
  if (gap > kNearMissFraction * size) return "";
  if (gap > kOverlapRounding)
    return "starts " + significant_digits(gap) + " m " + (depth > 0.0 ? "inside" : "above") +
           " the ground";
  if (body.shape != Shape::Box) return "";
  // The ground's normal in the box's frame: its largest part is the cosine of the turn
  // from the nearest face. The reference's own test of a box lying flat (sliding_modes.cpp)
  // wants that cosine within 1e-12 of 1.
  Vec3 local = (body.orientation.conjugate() * ground.normal).cwiseAbs();
  Eigen::Index face = 0;
  const double cosine = local.maxCoeff(&face);
  local[face] = 0.0;
  const double tilt = std::atan2(local.norm(), cosine);
  if (cosine >= 1.0 - 1e-12 || tilt > kNearMissTilt) return "";
  return "is turned " + significant_digits(tilt * 180.0 / std::numbers::pi) +
         " degrees from flat on the ground";
}

}  // namespace bb
