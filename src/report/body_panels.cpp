#include "report/body_panels.hpp"

#include <numeric>
#include <string>

namespace bb {

namespace {

/// The body an observable of the case is about, or -1 for an error metric or a number.
int claimed_body(const Scene& scene, const ClaimSide& side) {
  if (side.is_number()) return -1;
  for (const Observe& o : scene.observes)
    if (o.name == side.metric) return o.body;
  return -1;
}

/// The root of `i` in a union-find forest, halving the path on the way.
std::size_t root(std::vector<std::size_t>& parent, std::size_t i) {
  while (parent[i] != i) i = parent[i] = parent[parent[i]];
  return i;
}

}  // namespace

std::vector<std::vector<std::size_t>> body_panels(const Scene& scene, const std::vector<int>& drawn,
                                                  const std::vector<std::size_t>& slots) {
  // Union-find over the plotted slots: a claim between two of their bodies joins them.
  std::vector<std::size_t> parent(slots.size());
  std::iota(parent.begin(), parent.end(), std::size_t{0});
  const auto position_of = [&](int body) -> std::size_t {
    for (std::size_t i = 0; i < slots.size(); ++i)
      if (drawn[slots[i]] == body) return i;
    return slots.size();
  };
  for (const Claim& claim : scene.claims) {
    const std::size_t a = position_of(claimed_body(scene, claim.left));
    const std::size_t b = position_of(claimed_body(scene, claim.right));
    if (a < slots.size() && b < slots.size()) parent[root(parent, a)] = root(parent, b);
  }
  std::vector<std::vector<std::size_t>> panels;
  std::vector<std::size_t> panel_of_root(slots.size(), slots.size());
  for (std::size_t i = 0; i < slots.size(); ++i) {
    const std::size_t r = root(parent, i);
    if (panel_of_root[r] == slots.size()) {
      panel_of_root[r] = panels.size();
      panels.emplace_back();
    }
    panels[panel_of_root[r]].push_back(slots[i]);
  }
  return panels;
}

}  // namespace bb
