// The scene as it moves: every drawn body of every backend at report_dt over the
// reference's, as an SVG that plays by itself (SMIL animation: no script, no network) in a
// browser and on the Markdown page; and a still of chosen instants for print. Bodies are
// circles and boxes at their true size and turn, springs are lines, the ground and the
// fixed bodies are drawn once. Frames are thinned so that the file stays under
// kMotionViewBytes whatever the scene.
#pragma once

#include <string>
#include <vector>

#include "run/results.hpp"

namespace bb {

/// The size a motion view stays under.
inline constexpr std::size_t kMotionViewBytes = 1 << 20;

/// The animated view of `results` at report_dt. `drawn` lists the bodies whose states the
/// runs kept, in the order of a state's entries. Returns "" when no run has states.
std::string motion_svg(const CaseResults& results, const std::vector<int>& drawn);

/// The scene at each of `instants` (seconds), one panel each, every backend over the
/// reference; "" when no run has states.
std::string motion_still_svg(const CaseResults& results, const std::vector<int>& drawn,
                             const std::vector<double>& instants);

/// The instants a still shows: the start, the end, and two between.
std::vector<double> still_instants(const Scene& scene);

}  // namespace bb
