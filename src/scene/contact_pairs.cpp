#include "scene/contact_pairs.hpp"

namespace bb {

std::vector<ContactPair> contact_pairs(const Scene& scene) {
  std::vector<ContactPair> out;
  const int n = static_cast<int>(scene.bodies.size());
  if (scene.ground)
    for (int i = 0; i < n; ++i) {
      if (scene.bodies[i].fixed) continue;
      ContactPair pair{i, -1, scene.ground->restitution, scene.ground->friction_static,
                       scene.ground->friction_kinetic};
      // The first [[contact]] that names this body and the ground gives its own values.
      for (const Contact& c : scene.contacts)
        if (c.ground && c.body_a == i) {
          pair = {i, -1, c.restitution, c.friction_static, c.friction_kinetic};
          break;
        }
      out.push_back(pair);
    }
  std::vector<std::vector<bool>> paired(n, std::vector<bool>(n, false));
  for (const Contact& c : scene.contacts) {
    if (c.ground) continue;
    for (int a = 0; a < n; ++a)
      for (int b = a + 1; b < n; ++b) {
        const bool named =
            c.all_pairs || (c.body_a == a && c.body_b == b) || (c.body_a == b && c.body_b == a);
        if (!named || paired[a][b] || (scene.bodies[a].fixed && scene.bodies[b].fixed)) continue;
        paired[a][b] = true;
        const bool swap = scene.bodies[a].shape == Shape::Box;
        out.push_back(
            {swap ? b : a, swap ? a : b, c.restitution, c.friction_static, c.friction_kinetic});
      }
  }
  return out;
}

std::optional<ContactPair> ground_pair(const Scene& scene, int body) {
  for (const ContactPair& p : contact_pairs(scene))
    if (p.ground() && p.a == body) return p;
  return std::nullopt;
}

bool ground_rubs(const Scene& scene) {
  for (const ContactPair& p : contact_pairs(scene))
    if (p.ground() && (p.friction_static > 0.0 || p.friction_kinetic > 0.0)) return true;
  return false;
}

}  // namespace bb
