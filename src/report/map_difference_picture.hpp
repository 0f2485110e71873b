// The differences' small multiples: per backend but the reference, a panel of the map whose
// cells say where its outcome differs from the reference's at the same point
// (map_difference.hpp), with the theory's line where the backend has one, and one legend.
#pragma once

#include <string>

#include "run/results.hpp"

namespace bb {

/// Every backend's differences from the reference side by side ("" when the map has no
/// backend but the reference).
std::string map_differences_svg(const CaseResults& results);

}  // namespace bb
