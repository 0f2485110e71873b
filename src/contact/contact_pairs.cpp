#include "contact/contact_pairs.hpp"

namespace bb::contact {

namespace {

double radius(const Body& b) {
  return b.shape == Shape::Sphere ? b.radius : 0.0;
}

}  // namespace

std::vector<ContactPair> contact_pairs(const Scene& scene) {
  std::vector<ContactPair> out;
  const int n = static_cast<int>(scene.bodies.size());
  if (scene.ground)
    for (int i = 0; i < n; ++i)
      if (!scene.bodies[i].fixed) out.push_back({i, -1, scene.ground->restitution});
  std::vector<std::vector<bool>> paired(n, std::vector<bool>(n, false));
  for (const Contact& c : scene.contacts)
    for (int a = 0; a < n; ++a)
      for (int b = a + 1; b < n; ++b) {
        const bool named =
            c.all_pairs || (c.body_a == a && c.body_b == b) || (c.body_a == b && c.body_b == a);
        if (!named || paired[a][b] || (scene.bodies[a].fixed && scene.bodies[b].fixed)) continue;
        paired[a][b] = true;
        const bool swap = scene.bodies[a].shape == Shape::Box;
        out.push_back({swap ? b : a, swap ? a : b, c.restitution});
      }
  return out;
}

Proximity measure(const Scene& scene, const ContactPair& pair, const Eigen::Vector3d& xa,
                  const Eigen::Vector3d& xb, const Eigen::Quaterniond& qb) {
  const Body& a = scene.bodies[pair.a];
  if (pair.ground()) return sphere_plane(xa, radius(a), scene.ground->point, scene.ground->normal);
  const Body& b = scene.bodies[pair.b];
  if (b.shape == Shape::Box) return sphere_box(xa, radius(a), xb, qb, b.half_extents);
  return sphere_sphere(xa, radius(a), xb, radius(b));
}

}  // namespace bb::contact
