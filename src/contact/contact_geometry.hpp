// Contact geometry, written once for the course methods and the reference (engines use
// their own detection): where two shapes touch, how far apart they are, and along which
// normal. Pure functions of positions; no dynamics here.
#pragma once

#include <Eigen/Geometry>

namespace bb::contact {

/// How two shapes stand relative to each other at one instant.
struct Proximity {
  /// Signed distance between the surfaces, metres: positive apart, negative overlapping.
  double gap = 0.0;
  /// Unit normal pointing from the second shape towards the first; an impulse along it
  /// pushes the first shape away from the second.
  Eigen::Vector3d normal = Eigen::Vector3d::UnitY();
  /// The contact point, metres: on the second shape's surface.
  Eigen::Vector3d point = Eigen::Vector3d::Zero();
};

/// A sphere (centre, radius) against the infinite plane through `plane_point` with unit
/// `plane_normal`; the plane is the second shape, its solid side behind the normal.
Proximity sphere_plane(const Eigen::Vector3d& centre, double radius,
                       const Eigen::Vector3d& plane_point, const Eigen::Vector3d& plane_normal);

/// Sphere a against sphere b. Concentric spheres get the normal +y by convention.
Proximity sphere_sphere(const Eigen::Vector3d& centre_a, double radius_a,
                        const Eigen::Vector3d& centre_b, double radius_b);

/// A sphere against a box (centre, orientation, half extents): the box is the second shape.
/// Outside, the normal points from the box's closest surface point to the sphere's centre;
/// a centre inside the box is pushed out through the nearest face.
Proximity sphere_box(const Eigen::Vector3d& centre, double radius,
                     const Eigen::Vector3d& box_centre, const Eigen::Quaterniond& box_orientation,
                     const Eigen::Vector3d& half_extents);

/// A box (centre, orientation, half extents) against the infinite plane through
/// `plane_point` with unit `plane_normal`: the gap is the height of its lowest corner above
/// the plane, the point that corner's foot on the plane. A box lying on a face has four
/// lowest corners; the first in a fixed order stands for them.
Proximity box_plane(const Eigen::Vector3d& centre, const Eigen::Quaterniond& orientation,
                    const Eigen::Vector3d& half_extents, const Eigen::Vector3d& plane_point,
                    const Eigen::Vector3d& plane_normal);

/// A box turning about a hinge on one of its edges (the line through `axis_point` along the
/// unit `axis`), over a plane: the height above the plane of its lowest corner off that line
/// (the hinge's own corners touch all along). Zero or below: the box lies on the plane.
double clear_height(const Eigen::Vector3d& centre, const Eigen::Quaterniond& orientation,
                    const Eigen::Vector3d& half_extents, const Eigen::Vector3d& axis_point,
                    const Eigen::Vector3d& axis, const Eigen::Vector3d& plane_point,
                    const Eigen::Vector3d& plane_normal);

}  // namespace bb::contact
