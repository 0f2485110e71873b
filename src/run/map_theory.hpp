// The theories a map's boundary is drawn from: each bounds one parameter of the case (the
// step, the ground's tilt, ...) by a formula of the point's own parameters, for the backends
// it covers: below the bound the theory says the method holds (stable, the block held, the
// ball caught), above it not. A map draws, and its claims (`region = "theory"`) are judged
// against, the first theory whose parameter is one of its axes and that covers the backend at
// every value of the other axis: map_theory() is that choice, map_boundary() the line.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "study/scene.hpp"

namespace bb {

struct MapTheory {
  std::string bounded;  ///< the parameter it bounds, as a [[sweep]] names it ("dt")
  std::string column;   ///< the page's column for the bound: "theory's largest stable step"
  std::string line;     ///< the legend's words for the line, with the side that holds
  std::string page;     ///< what the map's page says of the line, in sentences
  std::string covers;   ///< what it bounds, for whom, as a refusal names it
  /// The bound at one point of the map for `backend`, in the parameter's own unit; nullopt
  /// where the theory does not cover the point or the backend.
  std::function<std::optional<double>(const Scene& point, const std::string& backend)> bound;
};

/// Every theory a map can draw, in the order they are tried.
const std::vector<MapTheory>& map_theories();

/// The theory drawn on `backend`'s map and judged by its claims: the first of map_theories()
/// that bounds one of the map's axes and covers the backend at every value of the other;
/// nullptr when none does (an engine under the stability theory, a scene with contacts).
const MapTheory* map_theory(const Scene& scene, const std::string& backend);

/// Whether `theory` bounds the map's first [[sweep]] (up the side), else its second.
bool bounds_first_sweep(const Scene& scene, const MapTheory& theory);

/// That theory's boundary: per value of the axis it does not bound (ascending), the bound
/// there; empty without a theory. A step's bound of 0 means unstable at every step (explicit
/// Euler on an undamped spring).
struct BoundaryPoint {
  double value = 0.0;  ///< of the axis the theory does not bound
  double limit = 0.0;  ///< on the bounded axis, in its parameter's unit
};
std::vector<BoundaryPoint> map_boundary(const Scene& scene, const std::string& backend);

/// What the theories bound and for whom, in one sentence: "the step (dt), for ...; ...".
std::string map_theories_cover();

}  // namespace bb
