#include "contact/contact_geometry.hpp"

#include <algorithm>
#include <limits>

namespace bb::contact {

Proximity sphere_plane(const Eigen::Vector3d& centre, double radius,
                       const Eigen::Vector3d& plane_point, const Eigen::Vector3d& plane_normal) {
  const double height = (centre - plane_point).dot(plane_normal);
  return {height - radius, plane_normal, centre - height * plane_normal};
}

Proximity sphere_sphere(const Eigen::Vector3d& centre_a, double radius_a,
                        const Eigen::Vector3d& centre_b, double radius_b) {
  const Eigen::Vector3d apart = centre_a - centre_b;
  const double distance = apart.norm();
  const Eigen::Vector3d normal =
      distance > 0.0 ? Eigen::Vector3d(apart / distance) : Eigen::Vector3d::UnitY();
  return {distance - radius_a - radius_b, normal, centre_b + radius_b * normal};
}

Proximity sphere_box(const Eigen::Vector3d& centre, double radius,
                     const Eigen::Vector3d& box_centre, const Eigen::Quaterniond& box_orientation,
                     const Eigen::Vector3d& half_extents) {
  // Work in the box's own frame, where it is axis-aligned about the origin.
  const Eigen::Matrix3d to_world = box_orientation.normalized().toRotationMatrix();
  const Eigen::Vector3d local = to_world.transpose() * (centre - box_centre);
  const Eigen::Vector3d closest = local.cwiseMax(-half_extents).cwiseMin(half_extents);
  const Eigen::Vector3d outside = local - closest;
  if (outside.squaredNorm() > 0.0) {
    const double distance = outside.norm();
    return {distance - radius, to_world * (outside / distance), box_centre + to_world * closest};
  }
  // The centre is inside: leave through the face with the least depth.
  const Eigen::Vector3d depth = half_extents - local.cwiseAbs();
  Eigen::Index axis = 0;
  depth.minCoeff(&axis);
  Eigen::Vector3d normal_local = Eigen::Vector3d::Zero();
  normal_local[axis] = local[axis] >= 0.0 ? 1.0 : -1.0;
  Eigen::Vector3d surface = local;
  surface[axis] = normal_local[axis] * half_extents[axis];
  return {-depth[axis] - radius, to_world * normal_local, box_centre + to_world * surface};
}

Proximity box_plane(const Eigen::Vector3d& centre, const Eigen::Quaterniond& orientation,
                    const Eigen::Vector3d& half_extents, const Eigen::Vector3d& plane_point,
                    const Eigen::Vector3d& plane_normal) {
  const Eigen::Matrix3d to_world = orientation.normalized().toRotationMatrix();
  // The normal in the box's frame: the lowest corner takes each axis's sign against it.
  const Eigen::Vector3d down = -(to_world.transpose() * plane_normal);
  Eigen::Vector3d corner;
  for (int k = 0; k < 3; ++k) corner[k] = down[k] >= 0.0 ? half_extents[k] : -half_extents[k];
  const Eigen::Vector3d lowest = centre + to_world * corner;
  const double height = (lowest - plane_point).dot(plane_normal);
  return {height, plane_normal, lowest - height * plane_normal};
}

double clear_height(const Eigen::Vector3d& centre, const Eigen::Quaterniond& orientation,
                    const Eigen::Vector3d& half_extents, const Eigen::Vector3d& axis_point,
                    const Eigen::Vector3d& axis, const Eigen::Vector3d& plane_point,
                    const Eigen::Vector3d& plane_normal) {
  const Eigen::Matrix3d to_world = orientation.normalized().toRotationMatrix();
  // A corner within this distance of the hinge's line is on it.
  const double on_axis = 1e-9 * (1.0 + half_extents.maxCoeff());
  double lowest = std::numeric_limits<double>::infinity();
  for (int k = 0; k < 8; ++k) {
    const Eigen::Vector3d local((k & 1) ? half_extents.x() : -half_extents.x(),
                                (k & 2) ? half_extents.y() : -half_extents.y(),
                                (k & 4) ? half_extents.z() : -half_extents.z());
    const Eigen::Vector3d corner = centre + to_world * local;
    const Eigen::Vector3d from_axis = corner - axis_point;
    if ((from_axis - from_axis.dot(axis) * axis).norm() <= on_axis) continue;
    lowest = std::min(lowest, (corner - plane_point).dot(plane_normal));
  }
  return lowest;
}

}  // namespace bb::contact
