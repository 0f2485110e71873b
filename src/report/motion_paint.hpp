// How the motion view paints a run: its stroke and fill by the backend's style, its springs'
// colour, its label and the legend.
#pragma once

#include <string>
#include <vector>

#include "report/xml_text.hpp"
#include "run/results.hpp"

namespace bb::motion {

/// Stroke and fill of a run: the reference filled grey under the others, the course methods
/// in solid lines, the engines dashed; `thick` scales the lines (small panels).
std::string paint(const std::string& backend, double thick);

/// The colour of a run's springs.
std::string spring_colour(const std::string& backend);

/// The run's backend, and its status when it is not ok, for a title or the legend.
std::string run_label(const RunRecord& run);

/// A legend entry per run, from (x, y).
std::string legend_svg(const std::vector<const RunRecord*>& runs, double x, double y);
/// The lowest point legend_svg draws for `runs` entries from y (the last line's descent).
double legend_bottom(std::size_t runs, double y);

}  // namespace bb::motion
