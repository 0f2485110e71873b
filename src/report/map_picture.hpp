// A map (two [[sweep]]s) drawn as SVG by the program itself: per backend a grid of cells,
// the first parameter up the side and the second along the bottom (each ascending), each
// cell coloured by the run's outcome at that point (map_cells.hpp), with the theory's
// boundary on top where a theory bounds one axis (map_theory.hpp): to its left (or below)
// the theory says the method holds, to its right (or above) not. The small multiples put every
// backend's map side by side with one legend, so that a class compares where each one holds and
// where it breaks.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "report/map_cells.hpp"
#include "run/results.hpp"

namespace bb {

/// The backends of a map's points, the reference first, in the order the points list them.
std::vector<std::string> map_backends(const CaseResults& results);

/// The file one backend's map is drawn in: "<case>-map-<backend>.svg", each '/' and '+'
/// of the name a '-'.
std::string map_file(const Scene& scene, const std::string& backend);

/// The file of the small multiples: "<case>-map.svg".
std::string map_multiples_file(const Scene& scene);

/// One backend's map, a picture of its own.
std::string map_svg(const CaseResults& results, const std::string& backend);

/// Every backend's map side by side, one legend.
std::string map_multiples_svg(const CaseResults& results);

/// What a panel's cell shows: its colour, the words its tooltip gives after the point's
/// values, and a mark drawn on it (a cross, a ring, a question mark) or none.
enum class MapMark { None, Cross, Ring, Question };
struct MapCell {
  std::string fill;
  std::string words;
  MapMark mark = MapMark::None;
};
using MapCellPaint = std::function<MapCell(const SweepPoint&)>;

/// A panel of the map titled `heading` with its top left corner at (`x`, `y`), each point's
/// cell as `paint` gives it, and `backend`'s theory line on top where it has one.
std::string map_panel(const CaseResults& results, const std::string& backend,
                      const std::string& heading, double x, double y, const MapCellPaint& paint);

/// A bold 12 px character (a panel's title, a claim's verdict) is about this wide, in px.
inline constexpr double kMapBoldCharWidth = 7.4;

/// An SVG's opening (white background, its title) and the size of one panel, for pictures
/// made of map panels.
std::string map_svg_opening(double width, double height, const std::string& title);
double map_panel_width(const Scene& scene);
/// An outcome's colour on the maps, and the outcomes' legend at `y` (with `backend`'s theory's
/// line where one bounds its map; no colour bar), for pictures of a map's outcomes.
std::string map_outcome_fill(MapOutcome outcome);
std::string map_outcomes_legend(const CaseResults& results, double y, const std::string& backend);
double map_panel_height(const Scene& scene);

/// The boundary's line in a panel whose cells start at (`left`, `top`) and are `cell` px
/// wide and high: the "x,y" pairs of its SVG polyline, one per value of the axis the theory
/// does not bound, or "" without a boundary. A bound below the bounded axis's first value
/// (a step of 0: unstable at every step) lies on that axis's start.
std::string boundary_points(const Scene& scene, const std::string& backend, double left, double top,
                            double cell);

}  // namespace bb
