// What a map's picture is made of, apart from the drawing: each backend's outcome at each
// point (ok, past the sweep's onset, diverged, unsupported, failed), the axes in ascending
// order with where a value sits along them, and the theory's boundary where one axis is the
// step: per value of the other axis, the largest stable step the course text's theory gives
// the backend's integrator there (the same function the stability search states).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "run/map_outcome.hpp"
#include "run/results.hpp"

namespace bb {

/// One axis of a map: its parameter, and its values ascending with the case's index of each.
struct MapAxis {
  std::string parameter;
  std::vector<double> values;      ///< ascending
  std::vector<std::size_t> index;  ///< index[k]: the case's index of values[k]
};

/// The first [[sweep]] (up the side) and the second (along the bottom) of a map's scene.
MapAxis map_rows(const Scene& scene);
MapAxis map_columns(const Scene& scene);

/// Where `value` lies along `axis`, in cells from its start: k + 0.5 at values[k]; between
/// two values linearly in their logarithms when both are positive (steps and stiffnesses
/// are spaced by factors), else linearly; held to [0, count] outside them.
double axis_position(const MapAxis& axis, double value);

/// The theory's boundary for `backend` on the map: per value of the axis that is not "dt"
/// (ascending), the largest stable step there. Empty without a "dt" axis or where the
/// theory does not cover the backend (an engine, a scene with contacts); 0 in a point means
/// unstable at every step (explicit Euler on an undamped spring).
struct BoundaryPoint {
  double value = 0.0;  ///< of the axis that is not "dt"
  double dt = 0.0;
};
std::vector<BoundaryPoint> map_boundary(const Scene& scene, const std::string& backend);

}  // namespace bb
