#include "metrics/stability_theory.hpp"

#include <cmath>
#include <limits>

namespace bb {

std::optional<TheoreticalLimit> theoretical_limit(const Scene& scene,
                                                  const std::string& integrator) {
  // Covered: bodies under gravity and quadratic drag (with or without wind), nothing else.
  const FeatureSet allowed{Feature::ThreeD, Feature::Gravity, Feature::Drag, Feature::Wind};
  const FeatureSet used = scene.features();
  if (!used.has(Feature::Drag) || !used.has(Feature::Gravity) ||
      !used.missing_from(allowed).empty())
    return std::nullopt;
  // Linearised about the terminal velocity, the velocity relaxes at rate lambda = 2 g / v_t,
  // v_t = sqrt(2 m g / (rho Cd A)); the stiffest body (smallest v_t) sets the limit.
  const double g = scene.gravity.norm();
  double vt_min = std::numeric_limits<double>::infinity();
  for (const Body& b : scene.bodies) {
    if (b.fixed || b.drag_coefficient <= 0.0) continue;
    const double k = 0.5 * scene.air->density * b.drag_coefficient * frontal_area(b);
    vt_min = std::min(vt_min, std::sqrt(b.mass * g / k));
  }
  // Each method is stable while lambda dt stays inside its stability interval on the
  // negative real axis: 2 for Euler (either order) and for the Heun-like velocity update
  // of velocity Verlet, 2.785 for RK4.
  const double t = vt_min / g;
  if (integrator == "explicit-euler" || integrator == "semi-implicit-euler")
    return TheoreticalLimit{t, "v_t / g: Euler on the drag relaxation 2 g / v_t"};
  if (integrator == "velocity-verlet")
    return TheoreticalLimit{t, "v_t / g: second-order velocity update on the drag relaxation"};
  if (integrator == "rk4")
    return TheoreticalLimit{2.785 / 2.0 * t, "1.39 v_t / g: RK4 on the drag relaxation"};
  return std::nullopt;
}

}  // namespace bb
