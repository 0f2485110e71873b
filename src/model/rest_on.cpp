#include "model/rest_on.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "model/initial_overlap.hpp"
#include "model/text.hpp"

namespace bb {

namespace {

/// How far `box` reaches from its centre along the unit `n` (its depth below a plane
/// through its centre).
double box_reach_along(const Body& box, const Vec3& n) {
  Ground through_centre;
  through_centre.point = box.position;
  through_centre.normal = n;
  return ground_depth(box, through_centre);
}

/// How far `body` reaches below its centre once turned to rest (its y axis along the normal).
double resting_reach(const Body& body) {
  if (body.shape == Shape::Box) return body.half_extents.y();
  return body.shape == Shape::Sphere ? body.radius : 0.0;
}

/// Whether `offset` (in a box's frame) is within its half extents on the two axes other
/// than `up_axis`.
bool within_face(const Vec3& offset, const Vec3& half_extents, Eigen::Index up_axis) {
  for (Eigen::Index k = 0; k < 3; ++k)
    if (k != up_axis && std::abs(offset[k]) > half_extents[k]) return false;
  return true;
}

}  // namespace

std::string place_on_body(Body& body, const Body& below, const Vec3& up) {
  if (below.shape == Shape::Point) return "'" + below.name + "' is a point: nothing rests on it";
  if (body.shape == Shape::Box) body.orientation = Quat::FromTwoVectors(Vec3::UnitY(), up);
  const double reach = resting_reach(body);
  const Vec3 between = body.position - below.position;
  const Vec3 offset = between - between.dot(up) * up;
  double height = 0.0;  // of body's centre above below's, along up
  if (below.shape == Shape::Box) {
    const Vec3 local_up = below.orientation.conjugate() * up;
    Eigen::Index axis = 0;
    if (local_up.cwiseAbs().maxCoeff(&axis) < 1.0 - 1e-12)
      return "box '" + below.name + "' has no face turned up (against gravity) to rest on";
    if (!within_face(below.orientation.conjugate() * offset, below.half_extents, axis))
      return "'" + body.name + "' is not over the top face of box '" + below.name + "'";
    height = below.half_extents[axis] + reach;
  } else if (body.shape == Shape::Box) {
    if (!within_face(body.orientation.conjugate() * offset, body.half_extents, 1))
      return "the top of sphere '" + below.name + "' is not under the bottom face of box '" +
             body.name + "'";
    height = below.radius + reach;
  } else {
    const double touching = below.radius + reach;
    if (offset.norm() >= touching)
      return "'" + body.name + "' is not over sphere '" + below.name + "'";
    height = std::sqrt(touching * touching - offset.squaredNorm());
  }
  body.position = below.position + offset + height * up;
  return "";
}

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
  // A ball a hair off the ground lands on it, or is on its way: only a box is lost to the
  // reference by it.
  if (body.shape != Shape::Box) return "";
  const double size = box_reach_along(body, ground.normal);
  const double depth = ground_depth(body, ground);
  const double gap = std::abs(depth);
  if (gap > kNearMissFraction * size) return "";
  if (gap > kOverlapRounding)
    return "starts " + significant_digits(gap) + " m " + (depth > 0.0 ? "inside" : "above") +
           " the ground";
  // Within rounding of the ground: flat on a face, or turned from it on purpose? The ground's
  // normal in the box's frame: its largest part is the cosine of the turn from the nearest face.
  // The reference's own test of a box lying flat (sliding_modes.cpp) wants that cosine within 1e-12
  // of 1.
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
