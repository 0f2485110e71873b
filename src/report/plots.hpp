// The plots of a case, drawn with gnuplot as SVG: work-precision per chosen metric, and
// the main coordinate and the energy of each body against time at report_dt.
#pragma once

#include <string>
#include <vector>

#include "run/results.hpp"

namespace bb {

struct PlotFiles {
  /// (metric, file name) per work-precision diagram.
  std::vector<std::pair<std::string, std::string>> work_precision;
  std::string trajectory;  ///< file name, empty when not drawn
  std::string energy;
  std::string note;  ///< why plots are missing, when they are
};

/// Draws every plot of the case into `dir` (file names start with the case name).
PlotFiles write_plots(const CaseResults& results, const std::string& dir);

}  // namespace bb
