// A map (two [[sweep]]s) on its case's page: what was run, the small multiples of every
// backend's map with a link to each one's own picture, and per backend how many points
// had each outcome and how many lie on the unstable side of the theory's boundary.
#pragma once

#include <string>
#include <vector>

#include "run/results.hpp"

namespace bb {

/// The map's pictures as written: the small multiples, and (backend, file) for each; the
/// differences from the reference.
struct MapFiles {
  std::string multiples;
  std::string differs;
  std::vector<std::pair<std::string, std::string>> backends;
};

/// The page's map section ("" for a case without a map).
std::string map_markdown(const CaseResults& results, const MapFiles& files);

}  // namespace bb
