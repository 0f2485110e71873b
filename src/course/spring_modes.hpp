// The stiffest mode of a scene's spring network, linearised at the start: the largest
// eigenvalue of M^-1 K (K from each spring's axial stiffness k u u^T), and its damping
// rate where every spring has the same damping-to-stiffness ratio (then C = r K and each
// mode's rate is r omega^2).
#pragma once

#include <optional>
#include <string>

#include "scene/scene.hpp"

namespace bb {

struct StiffestMode {
  double omega = 0.0;         ///< rad/s
  double damping_rate = 0.0;  ///< 1/s, gamma in x'' = -omega^2 x - gamma x'
  bool damping_known = true;  ///< false when the springs' damping ratios differ (left out)
  std::string how;            ///< how omega was found, in words
};

/// nullopt when the scene has no spring between moving bodies.
std::optional<StiffestMode> stiffest_mode(const World& scene);

/// The largest step (s) for which `integrator`'s step matrix on x'' = -omega^2 x - gamma x'
/// has a spectral radius of at most 1, found by bisection on the course's own step
/// function; 0 when no step is stable (explicit Euler on an undamped spring).
double linear_stability_limit(const std::string& integrator, double omega, double gamma);

}  // namespace bb
