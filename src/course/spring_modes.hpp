// The stiffest mode of a scene, linearised at the start: the largest eigenvalue of M^-1 K,
// K = -dF/dx the force model's stiffness (each term gives its own: a spring's k u u^T plus
// its tension across it), and its damping rate v^T C v on the mode's own shape v (the damping
// C = -dF/dv, mass-weighted: exact where C = r K, every spring with the same
// damping-to-stiffness ratio, when each mode's rate is r omega^2).
#pragma once

#include <optional>
#include <string>

#include "model/world.hpp"

namespace bb {

struct StiffestMode {
  double omega = 0.0;         ///< rad/s
  double damping_rate = 0.0;  ///< 1/s, gamma in x'' = -omega^2 x - gamma x'
  std::string how;            ///< how omega was found, in words
};

/// nullopt when no force stiffens the moving bodies.
std::optional<StiffestMode> stiffest_mode(const World& scene);

/// The largest step (s) for which `integrator`'s step matrix on x'' = -omega^2 x - gamma x'
/// has a spectral radius of at most 1, found by bisection on the course's own step
/// function; 0 when no step is stable (explicit Euler on an undamped spring).
double linear_stability_limit(const std::string& integrator, double omega, double gamma);

}  // namespace bb
