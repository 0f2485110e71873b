// Springs of seed section 7 (Hooke's law, with a damper along the spring), laid out for the
// force loop: index pairs and per-spring constants in separate arrays, built once per run.
// The loop is in this header so that each caller's step inlines it: no call, no
// allocation and no virtual dispatch per spring.
#pragma once

#include <cmath>
#include <vector>

#include "model/state.hpp"
#include "model/world.hpp"

namespace bb {

/// The scene's springs as structure of arrays.
struct SpringNetwork {
  std::vector<int> a, b;            ///< body indices, one pair per spring
  std::vector<double> stiffness;    ///< N/m
  std::vector<double> damping;      ///< N s/m, along the spring
  std::vector<double> rest_length;  ///< m
  std::size_t size() const { return a.size(); }
  bool empty() const { return a.empty(); }
};

SpringNetwork spring_network(const World& scene);

/// Adds every spring's force to `force` (N): k (l - L) + c (v_b - v_a).u along the unit
/// vector u from a to b, pulling a towards b when stretched; b gets the opposite. A spring
/// of zero length has no direction and no force.
inline void add_spring_forces(const SpringNetwork& s, const Vec3* x, const Vec3* v, Vec3* force) {
  const std::size_t n = s.size();
  for (std::size_t k = 0; k < n; ++k) {
    const int a = s.a[k], b = s.b[k];
    const Vec3 d = x[b] - x[a];
    const double length = d.norm();
    if (length == 0.0) continue;
    const Vec3 u = d / length;
    const double tension =
        s.stiffness[k] * (length - s.rest_length[k]) + s.damping[k] * (v[b] - v[a]).dot(u);
    force[a] += tension * u;
    force[b] -= tension * u;
  }
}

/// The same forces read from an engine's state (its bodies' positions and velocities), for
/// springs applied by hand before each engine step (`<engine>/force`).
inline void add_spring_forces(const SpringNetwork& s, const std::vector<BodyState>& state,
                              Vec3* force) {
  const std::size_t n = s.size();
  for (std::size_t k = 0; k < n; ++k) {
    const int a = s.a[k], b = s.b[k];
    const Vec3 d = state[b].position - state[a].position;
    const double length = d.norm();
    if (length == 0.0) continue;
    const Vec3 u = d / length;
    const double tension = s.stiffness[k] * (length - s.rest_length[k]) +
                           s.damping[k] * (state[b].velocity - state[a].velocity).dot(u);
    force[a] += tension * u;
    force[b] -= tension * u;
  }
}

/// Potential energy stored in the springs at positions `x` (J): sum of k (l - L)^2 / 2.
inline double spring_energy(const SpringNetwork& s, const Vec3* x) {
  double e = 0.0;
  for (std::size_t k = 0; k < s.size(); ++k) {
    const double stretch = (x[s.b[k]] - x[s.a[k]]).norm() - s.rest_length[k];
    e += 0.5 * s.stiffness[k] * stretch * stretch;
  }
  return e;
}

}  // namespace bb
