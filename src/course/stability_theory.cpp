#include "course/stability_theory.hpp"

#include <cmath>
#include <limits>
#include <sstream>

#include "course/spring_modes.hpp"
#include "scene/text.hpp"

namespace bb {

namespace {

/// Springs: the integrator on the network's stiffest mode, with its damping where known.
std::optional<TheoreticalLimit> spring_limit(const World& scene, const std::string& integrator) {
  const auto mode = stiffest_mode(scene);
  if (!mode) return std::nullopt;
  const double limit = linear_stability_limit(integrator, mode->omega, mode->damping_rate);
  std::string formula = "stiffest mode omega_max = " + significant_digits(mode->omega, 4) +
                        " rad/s (" + mode->how + ")";
  if (mode->damping_rate > 0.0)
    formula += ", damping rate " + significant_digits(mode->damping_rate, 4) + " /s";
  else if (!mode->damping_known)
    formula += "; the springs' damping ratios differ, so damping is left out";
  if (limit == 0.0)
    return TheoreticalLimit{0.0,
                            "unstable at every dt: " + integrator +
                                "'s step grows every undamped oscillation; " + formula,
                            ""};
  const bool textbook = mode->damping_rate == 0.0 &&
                        (integrator == "semi-implicit-euler" || integrator == "velocity-verlet");
  return TheoreticalLimit{limit,
                          (textbook ? "2 / omega_max, "
                                    : "largest step whose step matrix on the mode has "
                                      "spectral radius 1, ") +
                              formula,
                          ""};
}

}  // namespace

std::optional<TheoreticalLimit> theoretical_limit(const World& scene,
                                                  const std::string& integrator) {
  // Springs and nothing that touches: the stiffest mode sets the limit.
  if (scene.features().has(Feature::Springs) && !scene.features().has(Feature::GroundContact) &&
      !scene.features().has(Feature::BodyContact))
    return spring_limit(scene, integrator);
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
  const std::string note =
      "Past this line Euler's velocity overshoots the terminal speed each step, but the drag "
      "grows with the square of the speed and pulls it back: the oscillation stays bounded, "
      "so a measured stable step above the line is no contradiction.";
  if (integrator == "explicit-euler" || integrator == "semi-implicit-euler")
    return TheoreticalLimit{t, "v_t / g: Euler on the drag relaxation 2 g / v_t", note};
  if (integrator == "velocity-verlet")
    return TheoreticalLimit{t, "v_t / g: second-order velocity update on the drag relaxation",
                            note};
  if (integrator == "rk4")
    return TheoreticalLimit{2.785 / 2.0 * t, "1.39 v_t / g: RK4 on the drag relaxation", note};
  return std::nullopt;
}

}  // namespace bb
