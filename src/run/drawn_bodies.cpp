#include "run/drawn_bodies.hpp"

#include <algorithm>
#include <cmath>

namespace bb {

namespace {

/// `count` indices from 0 to n - 1, evenly spread, both ends included.
std::vector<int> spread(int n, int count) {
  std::vector<int> out;
  if (n <= 0) return out;
  count = std::clamp(count, 1, n);
  for (int i = 0; i < count; ++i) {
    const int at =
        count == 1 ? 0 : static_cast<int>(std::lround(double(i) * (n - 1) / (count - 1)));
    if (out.empty() || at != out.back()) out.push_back(at);
  }
  return out;
}

}  // namespace

std::vector<int> drawn_bodies(const Scene& scene) {
  const int n = static_cast<int>(scene.bodies.size());
  std::vector<int> out;
  if (static_cast<std::size_t>(n) <= kDrawnBodies) {
    for (int b = 0; b < n; ++b) out.push_back(b);
    return out;
  }
  // A wave surface: points spread along it, both ends included, so the whole profile shows.
  if (scene.waves) {
    for (int i : spread(scene.waves->points, static_cast<int>(kDrawnBodies)))
      out.push_back(scene.waves->first_body + i);
    return out;
  }
  if (!scene.grid) {
    for (int b = 0; b < static_cast<int>(kDrawnBodies); ++b) out.push_back(b);
    return out;
  }
  // The bodies that are not the grid's particles first (a ball on the cloth), then a lattice
  // of the grid: as many particles per side as the rest allows, its edges included.
  const Grid& g = *scene.grid;
  const int cols = g.size[0], rows = g.size.size() > 1 ? g.size[1] : 1,
            depth = g.size.size() > 2 ? g.size[2] : 1;
  const int last = g.first_body + cols * rows * depth;
  for (int b = 0; b < n && out.size() < kDrawnBodies / 4; ++b)
    if (b < g.first_body || b >= last) out.push_back(b);
  const double room = static_cast<double>(kDrawnBodies - out.size());
  const int sides = static_cast<int>(g.size.size());
  const int per_side =
      std::max(2, static_cast<int>(std::floor(std::pow(room, 1.0 / sides) + 1e-9)));
  for (int k : spread(depth, per_side))
    for (int j : spread(rows, per_side))
      for (int i : spread(cols, per_side)) out.push_back(g.first_body + (k * rows + j) * cols + i);
  return out;
}

std::optional<std::size_t> drawn_slot(const std::vector<int>& drawn, int body) {
  const auto it = std::find(drawn.begin(), drawn.end(), body);
  if (it == drawn.end()) return std::nullopt;
  return static_cast<std::size_t>(it - drawn.begin());
}

}  // namespace bb
