// Which bodies share a panel on the plots of a case: the bodies one claim compares (the
// elephant and the mouse, the backspin and the topspin throw) are drawn together on one
// scale, so the comparison the claim makes is the one the reader sees; every other body
// has its own panel.
#pragma once

#include <cstddef>
#include <vector>

#include "study/scene.hpp"

namespace bb {

/// `slots` (positions in `drawn`, the scene's drawn body indices) grouped into panels: a
/// claim whose two sides are observables of two different bodies joins their groups. The
/// groups keep the order of their first slot, and each group the order of `slots`.
std::vector<std::vector<std::size_t>> body_panels(const Scene& scene, const std::vector<int>& drawn,
                                                  const std::vector<std::size_t>& slots);

}  // namespace bb
