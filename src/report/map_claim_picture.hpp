// A map's claim drawn (a [[claim]] with `region`): the backend's map of outcomes with the
// theory's line, each point where the claim failed crossed out, each point within the
// claim's margin of the boundary ringed (not judged), and a point without an outcome marked
// with a question mark; the verdict under it.
#pragma once

#include <cstddef>
#include <string>

#include "run/results.hpp"

namespace bb {

/// The file of the case's claim number `k` (from 0, in the case's order) when it is a map's
/// claim: "<case>-claim-<k + 1>.svg".
std::string map_claim_file(const Scene& scene, std::size_t k);

/// The picture of `claim`, a map's claim of `results` judged into `claim`'s one verdict.
std::string map_claim_svg(const CaseResults& results, const ClaimResult& claim);

}  // namespace bb
