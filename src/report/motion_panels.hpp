// Where the motion view's panels sit on the picture: one scene at full size, or small ones
// in columns (a panel per run, or per instant), each a scaled, clipping viewport of the
// canvas with its name above it.
#pragma once

#include <string>
#include <vector>

#include "report/motion_geometry.hpp"

namespace bb::motion {

inline constexpr double kCanvasWidth = 760.0;  ///< pixels of one scene drawn at full size
inline constexpr double kMargin = 10.0;
inline constexpr double kGap = 12.0;         ///< between small panels
inline constexpr double kPanelTitle = 18.0;  ///< a panel's name above it

/// Where a panel sits on the page and how wide it is; the canvas fills it, scaled.
struct Panel {
  double x = 0.0, y = 0.0, width = 0.0;
  std::string title;
};

/// A panel's title and the opening of its scaled, clipping viewport (closed by "</svg>").
std::string open_panel(const Panel& p, const Canvas& c);

/// How tall a panel is on the page, its name included.
double panel_height(const Panel& p, const Canvas& c);

/// Panels for `count` runs from `top`: one at full size, or small ones in `columns`.
std::vector<Panel> layout(std::size_t count, bool multiples, const Canvas& c, double columns,
                          double top);

}  // namespace bb::motion
