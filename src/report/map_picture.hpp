// A map (two [[sweep]]s) drawn as SVG by the program itself: per backend a grid of cells,
// the first parameter up the side and the second along the bottom (each ascending), each
// cell coloured by the run's outcome at that point (map_cells.hpp), with the theory's
// boundary on top where a theory bounds one axis (map_theory.hpp): to its left (or below)
// the theory says the method holds, to its right (or above) not. The small multiples put every
// backend's map side by side with one legend, so that a class compares where each one holds and
// where it breaks.
#pragma once

#include <string>
#include <vector>

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

/// The boundary's line in a panel whose cells start at (`left`, `top`) and are `cell` px
/// wide and high: the "x,y" pairs of its SVG polyline, one per value of the axis the theory
/// does not bound, or "" without a boundary. A bound below the bounded axis's first value
/// (a step of 0: unstable at every step) lies on that axis's start.
std::string boundary_points(const Scene& scene, const std::string& backend, double left, double top,
                            double cell);

}  // namespace bb
