// The bodies a run keeps the states of at report_dt, for the plots and the motion view:
// every body of a small scene; of a big one (a spring grid, a crowd), a lattice of the
// grid's particles that keeps the sheet's shape, and the first of the others; of a wave
// surface, points spread along it. A run's state
// at report_dt then holds these bodies, in this order.
#pragma once

#include <cstddef>
#include <optional>
#include <vector>

#include "study/scene.hpp"

namespace bb {

/// The most bodies a run keeps at report_dt.
inline constexpr std::size_t kDrawnBodies = 128;

/// The kept bodies' indices in the scene, in the order a kept state holds them.
std::vector<int> drawn_bodies(const Scene& scene);

/// Where body `body` sits in a kept state, or nullopt when it is not kept.
std::optional<std::size_t> drawn_slot(const std::vector<int>& drawn, int body);

}  // namespace bb
