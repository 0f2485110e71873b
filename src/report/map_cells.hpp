// What a map's picture is made of, apart from the drawing: each backend's outcome at each
// point (ok, past the sweep's onset, diverged, unsupported, failed), the axes in ascending
// order with where a value sits along them. The theory's boundary, where a theory bounds one
// axis, is run/map_theory.hpp's (map_theory(), map_boundary()), shared with the map's claims.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "run/map_outcome.hpp"
#include "run/map_theory.hpp"
#include "run/results.hpp"

namespace bb {

/// One axis of a map: its parameter, and its values ascending with the case's index of each.
struct MapAxis {
  std::string parameter;
  std::vector<double> values;      ///< ascending
  std::vector<std::size_t> index;  ///< index[k]: the case's index of values[k]
  /// Spaced by factors (all positive, not evenly spaced): steps, stiffnesses.
  bool logarithmic = false;
};

/// The first [[sweep]] (up the side) and the second (along the bottom) of a map's scene.
MapAxis map_rows(const Scene& scene);
MapAxis map_columns(const Scene& scene);

/// Where `value` lies along `axis`, in cells from its start: k + 0.5 at values[k]; between
/// two values linearly in their logarithms on a logarithmic axis, else linearly; held to
/// [0, count] outside them.
double axis_position(const MapAxis& axis, double value);

/// A theory's bound as a page says it: a step as seconds ("0.0707 s"), else the number.
std::string map_bound_text(const MapTheory& theory, double limit);

}  // namespace bb
