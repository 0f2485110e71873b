// The plots of a case, drawn with gnuplot as SVG: work-precision per chosen metric; at
// report_dt the main coordinate and the energy of each body against time, and each
// backend's distance from the reference against time (log scale); where a body's stop is
// observed, its slide and velocity around the stop (stop_plot.hpp); where a body turns,
// its angle and spin (rotation_plot.hpp). Long runs are thinned
// for drawing (each bucket keeps its lowest and highest point) so a page's SVG stays small.
#pragma once

#include <string>
#include <vector>

#include "files/file_batch.hpp"
#include "report/gnuplot.hpp"
#include "report/map_page.hpp"
#include "run/results.hpp"

namespace bb {

struct PlotFiles {
  /// (metric, file name) per work-precision diagram.
  std::vector<std::pair<std::string, std::string>> work_precision;
  std::string trajectory;  ///< file name, empty when not drawn
  std::string speed;       ///< speed against time, where air drags a body
  std::string energy;
  std::string error;     ///< distance from the reference against time
  std::string stop;      ///< sliding bodies around their stop; empty when none is observed
  std::string rotation;  ///< turning bodies' angle and spin; empty when none turns
  std::string sweep;     ///< the quantities against the swept parameter; empty without one
  MapFiles map;          ///< a map's pictures (two [[sweep]]s); empty without one
  std::string motion;    ///< the animated view of the scene (motion_view.hpp); empty when none
  std::string still;     ///< the scene at a few instants, for print
  std::string note;      ///< why plots are missing, when they are
};

/// Draws every plot of the case into `batch` (file names start with the case name). A plot
/// gnuplot could not write completely is a WriteError; gnuplot missing is a note.
PlotFiles write_plots(const CaseResults& results, FileBatch& batch);

/// Whether the case gets a speed-against-time plot: air drags one of its bodies (the
/// approach to a terminal speed is what such a case is about).
bool draws_speed(const Scene& scene);

/// The file names write_plots may use for `scene`.
std::vector<std::string> plot_file_names(const Scene& scene);

}  // namespace bb
