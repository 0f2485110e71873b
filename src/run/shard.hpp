// A share of a report's work, so that N machines (a Slurm job array, a CI matrix) each run
// one part and `beachball merge` puts the parts together. The work is split by a stable
// hash of the case's text and the unit: each backend's runs of a case (every dt, its cost
// and its stability search together, since they build on each other) and each point of a
// sweep. The reference is run by every shard that needs it (the runs are measured against
// it), and kept by each: the same bytes.
#pragma once

#include <optional>
#include <string>

#include "study/scene.hpp"

namespace bb {

struct Shard {
  int index = 1;  ///< 1 to count
  int count = 1;
};

/// Whether `unit` of `scene` is this shard's work (always, without a shard).
bool in_shard(const std::optional<Shard>& shard, const Scene& scene, const std::string& unit);

}  // namespace bb
