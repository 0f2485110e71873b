// The theories a map's boundary is drawn from: each bounds one parameter of the case (the
// step, the ground's tilt, ...) by a formula of the point's own parameters, for the backends
// it covers: below the bound the theory says the method holds (stable, the block held, the
// ball caught), above it not. A map draws the first theory whose parameter is one of its axes
// and that covers the backend at every value of the other axis.
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
  /// The bound at one point of the map for `backend`, in the parameter's own unit; nullopt
  /// where the theory does not cover the point or the backend.
  std::function<std::optional<double>(const Scene& point, const std::string& backend)> bound;
};

/// Every theory a map can draw, in the order they are tried.
const std::vector<MapTheory>& map_theories();

}  // namespace bb
