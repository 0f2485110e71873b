// A body's terminal fall, from the force model alone: the speed through the air at which
// the forces on it hold it against gravity, and how fast its velocity relaxes there. The
// terminal_velocity observable and the course's stability theory read it, so that a force's
// law (1/2 rho Cd A for drag) is written once, in its term.
#pragma once

#include <optional>
#include <string>

#include "model/world.hpp"

namespace bb {

struct TerminalFall {
  double speed = 0.0;  ///< m/s through the air: where the forces along gravity balance it
  double rate = 0.0;   ///< 1/s: -(g^ . dF/dv g^) / m there, the rate the velocity relaxes at
};

/// Body `body` of `scene` falling straight down through the air (its velocity the wind's
/// plus s along gravity, its spin as at the start, every other body as at the start).
/// nullopt, with the reason in `why`, when no force holds it against gravity by 1e12 m/s,
/// or when at that speed its forces also push it across its fall (a spin's Magnus force).
std::optional<TerminalFall> terminal_fall(const World& scene, int body, std::string* why = nullptr);

}  // namespace bb
