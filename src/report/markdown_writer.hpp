// The Markdown page of one case: the scene, the tables, the settings and versions.
#pragma once

#include <string>

#include "report/plots.hpp"
#include "run/results.hpp"

namespace bb {

/// `plots` names the SVG files drawn beside the page (none when empty).
std::string results_markdown(const CaseResults& results, const PlotFiles& plots = {});

}  // namespace bb
