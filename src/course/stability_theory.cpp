#include "course/stability_theory.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "course/spring_modes.hpp"
#include "model/text.hpp"
#include "physics/terminal_fall.hpp"

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
    formula += ", its damping rate " + significant_digits(mode->damping_rate, 4) + " /s";
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

/// Whether gravity hangs a spring network from a fixed body: it then also swings as a
/// pendulum, a mode with no stiffness at the start.
bool hangs(const World& scene) {
  if (scene.gravity.norm() == 0.0) return false;
  for (const Spring& s : scene.springs)
    if (scene.bodies[s.body_a].fixed != scene.bodies[s.body_b].fixed) return true;
  return false;
}

}  // namespace

std::optional<TheoreticalLimit> theoretical_limit(const World& scene,
                                                  const std::string& integrator) {
  // A stiffness and nothing that touches: the stiffest mode sets the limit.
  if (!scene.features().has(Feature::GroundContact) && !scene.features().has(Feature::BodyContact))
    if (auto limit = spring_limit(scene, integrator)) {
      if (hangs(scene))
        limit->note =
            "The network also swings as a pendulum under gravity. That swing has no stiffness at "
            "the start, so the limit above does not see it, and the springs' dampers act along "
            "the springs only, so nothing damps it: explicit Euler, which grows every undamped "
            "oscillation, is unstable on it at every step.";
      return limit;
    }
  // Covered: bodies under gravity and forces that hold them at a terminal speed (quadratic
  // drag, with or without wind), nothing else.
  const FeatureSet allowed{Feature::ThreeD, Feature::Gravity, Feature::Drag, Feature::Wind};
  const FeatureSet used = scene.features();
  if (!used.has(Feature::Drag) || !used.has(Feature::Gravity) ||
      !used.missing_from(allowed).empty())
    return std::nullopt;
  // Linearised about the terminal fall, the velocity relaxes at the force model's rate
  // lambda (2 g / v_t for quadratic drag); the fastest-relaxing body sets the limit.
  double rate = 0.0;
  for (std::size_t i = 0; i < scene.bodies.size(); ++i)
    if (!scene.bodies[i].fixed)
      if (const auto fall = terminal_fall(scene, static_cast<int>(i)))
        rate = std::max(rate, fall->rate);
  if (rate <= 0.0) return std::nullopt;
  // Each method is stable while lambda dt stays inside its stability interval on the
  // negative real axis: 2 for Euler (either order) and for the Heun-like velocity update
  // of velocity Verlet, 2.785 for RK4.
  const double t = 2.0 / rate;
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
