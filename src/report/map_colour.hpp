// A map coloured by an error (the first [[sweep]]'s `colour`): each ok point's error in that
// metric (an error metric, or an observable's difference from the reference's) as a colour on
// one scale for every backend's map, so that the small multiples compare; the scale runs from
// the smallest positive error on the map to the largest, logarithmic when they are more than
// ten apart, and a colour bar with both ends under the maps says so.
#pragma once

#include <optional>
#include <string>

#include "run/results.hpp"

namespace bb {

/// The scale of a map's colour over every backend's points; `metric` empty without one.
struct MapScale {
  std::string metric;
  double low = 0.0, high = 0.0;  ///< the smallest positive error and the largest
  bool logarithmic = false;
};

/// The scale of `results`' map (no metric when the case gives no `colour`, or no point
/// has a positive error in it).
MapScale map_scale(const CaseResults& results);

/// `run`'s error in the scale's metric, where the run is ok and has one.
std::optional<double> scaled_error(const MapScale& scale, const RunRecord* run);

/// The fill of `error` on the scale ("#rrggbb"): from pale yellow at or below `low` to dark
/// blue at `high` (the sequential YlGnBu of ColorBrewer, interpolated).
std::string scale_fill(const MapScale& scale, double error);

/// The colour bar with its ends and the metric's name, its top left corner at (`x`, `y`).
std::string scale_legend(const MapScale& scale, double x, double y);

}  // namespace bb
