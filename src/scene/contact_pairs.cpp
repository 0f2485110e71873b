#include "scene/contact_pairs.hpp"

namespace bb {

std::vector<ContactPair> contact_pairs(const Scene& scene) {
  std::vector<ContactPair> out;
  const int n = static_cast<int>(scene.bodies.size());
  if (scene.ground)
    for (int i = 0; i < n; ++i)
      if (!scene.bodies[i].fixed)
        out.push_back({i, -1, scene.ground->restitution, scene.ground->friction_static,
                       scene.ground->friction_kinetic});
  std::vector<std::vector<bool>> paired(n, std::vector<bool>(n, false));
  for (const Contact& c : scene.contacts)
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
  return out;
}

}  // namespace bb
