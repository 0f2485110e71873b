#include "model/initial_overlap.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace bb {

namespace {

double radius_of(const Body& b) {
  return b.shape == Shape::Sphere ? b.radius : 0.0;
}

/// Half the extent of `box` along the unit direction `n`.
double box_reach(const Body& box, const Vec3& n) {
  const Eigen::Matrix3d axes = box.orientation.toRotationMatrix();
  double reach = 0.0;
  for (int i = 0; i < 3; ++i) reach += box.half_extents[i] * std::abs(axes.col(i).dot(n));
  return reach;
}

/// A sphere (or point) against a box.
double sphere_box_depth(const Body& sphere, const Body& box) {
  const Vec3 local = box.orientation.conjugate() * (sphere.position - box.position);
  const Vec3& h = box.half_extents;
  const bool inside =
      std::abs(local.x()) <= h.x() && std::abs(local.y()) <= h.y() && std::abs(local.z()) <= h.z();
  if (inside) {
    // The centre is in the box: out through the nearest face.
    const double to_face = std::min(
        {h.x() - std::abs(local.x()), h.y() - std::abs(local.y()), h.z() - std::abs(local.z())});
    return radius_of(sphere) + to_face;
  }
  const Vec3 closest = local.cwiseMax(-h).cwiseMin(h);
  return radius_of(sphere) - (local - closest).norm();
}

/// Two boxes, by separating axes: the least overlap of their projections on the 15 axes
/// (each box's faces and the cross products of their edges); apart when one is negative.
double box_box_depth(const Body& a, const Body& b) {
  const Eigen::Matrix3d ra = a.orientation.toRotationMatrix();
  const Eigen::Matrix3d rb = b.orientation.toRotationMatrix();
  std::array<Vec3, 15> axes;
  int count = 0;
  for (int i = 0; i < 3; ++i) axes[count++] = ra.col(i);
  for (int i = 0; i < 3; ++i) axes[count++] = rb.col(i);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      const Vec3 c = ra.col(i).cross(rb.col(j));
      // Parallel edges give no axis of their own: the face axes cover them.
      if (c.norm() > 1e-9) axes[count++] = c.normalized();
    }
  const Vec3 between = b.position - a.position;
  double least = std::numeric_limits<double>::infinity();
  for (int k = 0; k < count; ++k) {
    const Vec3& n = axes[k];
    least = std::min(least, box_reach(a, n) + box_reach(b, n) - std::abs(between.dot(n)));
  }
  return least;
}

}  // namespace

double ground_depth(const Body& body, const Ground& ground) {
  const double height = (body.position - ground.point).dot(ground.normal);
  const double reach = body.shape == Shape::Box ? box_reach(body, ground.normal) : radius_of(body);
  return reach - height;
}

double overlap_depth(const Body& a, const Body& b) {
  if (a.shape == Shape::Box && b.shape == Shape::Box) return box_box_depth(a, b);
  if (a.shape == Shape::Box) return sphere_box_depth(b, a);
  if (b.shape == Shape::Box) return sphere_box_depth(a, b);
  return radius_of(a) + radius_of(b) - (a.position - b.position).norm();
}

}  // namespace bb
