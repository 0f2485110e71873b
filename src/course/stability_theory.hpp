// Theoretical stability limits of the course integrators, derived from the scene.
#pragma once

#include <optional>
#include <string>

#include "model/world.hpp"

namespace bb {

struct TheoreticalLimit {
  double dt = 0.0;      ///< seconds; 0: no step is stable
  std::string formula;  ///< how it was derived, in words
  std::string note;     ///< how to read the measured limit beside it, may be empty
};

/// The largest stable step theory predicts for `integrator` on `scene`, when the scene is
/// one theory covers; nullopt otherwise.
std::optional<TheoreticalLimit> theoretical_limit(const World& scene,
                                                  const std::string& integrator);

}  // namespace bb
