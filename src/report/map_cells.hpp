// What a map's picture is made of, apart from the drawing: each backend's outcome at each
// point (ok, past the sweep's onset, diverged, unsupported, failed), the axes in ascending
// order with where a value sits along them, and the theory's boundary where a theory bounds
// one axis (run/map_theory.hpp): per value of the other axis, the bound there (the course
// integrator's largest stable step, the steepest tilt a block holds on, ...).
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

/// The theory drawn on `backend`'s map: the first of map_theories() that bounds one of the
/// map's axes and covers the backend at every value of the other; nullptr when none does
/// (an engine under the stability theory, a scene with contacts).
const MapTheory* map_theory(const Scene& scene, const std::string& backend);

/// That theory's boundary: per value of the axis it does not bound (ascending), the bound
/// there; empty without a theory. A step's bound of 0 means unstable at every step (explicit
/// Euler on an undamped spring).
struct BoundaryPoint {
  double value = 0.0;  ///< of the axis the theory does not bound
  double limit = 0.0;  ///< on the bounded axis, in its parameter's unit
};
std::vector<BoundaryPoint> map_boundary(const Scene& scene, const std::string& backend);

}  // namespace bb
