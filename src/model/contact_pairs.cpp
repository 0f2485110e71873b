#include "model/contact_pairs.hpp"

#include <algorithm>
#include <set>

namespace bb {

std::vector<ContactPair> contact_pairs(const World& scene) {
  std::vector<ContactPair> out;
  const int n = static_cast<int>(scene.bodies.size());
  // A body's own [[contact]] with the ground, when it has one (the loader allows one each).
  std::vector<const Contact*> own_ground(static_cast<std::size_t>(n), nullptr);
  for (const Contact& c : scene.contacts)
    if (c.ground && own_ground[c.body_a] == nullptr) own_ground[c.body_a] = &c;
  if (scene.ground)
    for (int i = 0; i < n; ++i) {
      if (scene.bodies[i].fixed) continue;
      const Contact* c = own_ground[i];
      out.push_back(c ? ContactPair{i, -1, c->restitution, c->friction_static, c->friction_kinetic}
                      : ContactPair{i, -1, scene.ground->restitution, scene.ground->friction_static,
                                    scene.ground->friction_kinetic});
    }
  const auto add = [&](int a, int b, const Contact& c) {
    // The fixed body, when one takes part, is b; else a box is.
    const bool swap =
        scene.bodies[a].fixed || (!scene.bodies[b].fixed && scene.bodies[a].shape == Shape::Box);
    out.push_back(
        {swap ? b : a, swap ? a : b, c.restitution, c.friction_static, c.friction_kinetic});
  };
  // Pairs named one by one come first and win over ["*"], whatever the order of the entries.
  std::set<std::pair<int, int>> named;
  const Contact* every = nullptr;
  for (const Contact& c : scene.contacts) {
    if (c.ground) continue;
    if (c.all_pairs) {
      every = every ? every : &c;
      continue;
    }
    const int a = std::min(c.body_a, c.body_b), b = std::max(c.body_a, c.body_b);
    if (scene.bodies[a].fixed && scene.bodies[b].fixed) continue;
    if (named.insert({a, b}).second) add(a, b, c);
  }
  if (every == nullptr) return out;
  // Every pair a < b but those of two fixed bodies: a fixed `a` meets only the moving bodies
  // after it (a case of many fixed bodies does not cost their square).
  std::vector<int> moving;
  for (int i = 0; i < n; ++i)
    if (!scene.bodies[i].fixed) moving.push_back(i);
  for (int a = 0; a < n; ++a) {
    const auto add_if_free = [&](int b) {
      if (named.count({a, b}) == 0) add(a, b, *every);
    };
    if (scene.bodies[a].fixed) {
      for (auto b = std::upper_bound(moving.begin(), moving.end(), a); b != moving.end(); ++b)
        add_if_free(*b);
    } else {
      for (int b = a + 1; b < n; ++b) add_if_free(b);
    }
  }
  return out;
}

std::optional<ContactPair> ground_pair(const World& scene, int body) {
  for (const ContactPair& p : contact_pairs(scene))
    if (p.ground() && p.a == body) return p;
  return std::nullopt;
}

bool ground_rubs(const World& scene) {
  for (const ContactPair& p : contact_pairs(scene))
    if (p.ground() && (p.friction_static > 0.0 || p.friction_kinetic > 0.0)) return true;
  return false;
}

}  // namespace bb
