#include "contact/contact_pairs.hpp"

namespace bb::contact {

namespace {

double radius(const Body& b) {
  return b.shape == Shape::Sphere ? b.radius : 0.0;
}

}  // namespace

Proximity measure(const World& scene, const ContactPair& pair, const Eigen::Vector3d& xa,
                  const Eigen::Vector3d& xb, const Eigen::Quaterniond& qb) {
  const Body& a = scene.bodies[pair.a];
  if (pair.ground() && a.shape == Shape::Box)
    return box_plane(xa, qb, a.half_extents, scene.ground->point, scene.ground->normal);
  if (pair.ground()) return sphere_plane(xa, radius(a), scene.ground->point, scene.ground->normal);
  const Body& b = scene.bodies[pair.b];
  if (b.shape == Shape::Box) return sphere_box(xa, radius(a), xb, qb, b.half_extents);
  return sphere_sphere(xa, radius(a), xb, radius(b));
}

}  // namespace bb::contact
