// A map's claims ([[claim]] with `region`): at each point of the map, where the point's value
// of the axis the map's theory bounds lies against the region's boundary (that theory's bound
// for the backend at the point, run/map_theory.hpp's map_theory(), times the claim's
// boundary_factor: the largest stable step, the steepest tilt a block holds on, ...), and
// whether the backend's outcome there is the one the claim states for that side. Points
// within the claim's margin of the boundary are not judged.
#pragma once

#include <optional>
#include <vector>

#include "run/claim_result.hpp"
#include "run/map_outcome.hpp"
#include "run/results.hpp"

namespace bb {

/// Where a point lies for a map's claim.
enum class RegionPlace { Inside, Outside, WithinMargin, NoTheory };

/// One point of the map for a map's claim.
struct RegionPoint {
  RegionPlace place = RegionPlace::NoTheory;
  /// The region's boundary there, in the bounded parameter's unit, where a theory gives one.
  std::optional<double> boundary;
  MapOutcome outcome = MapOutcome::Absent;
  bool judged = false;  ///< on a side the claim states, with an outcome to judge
  bool held = false;    ///< judged, and the outcome is the one claimed
};

/// Each point of `results.sweep` (in its order) for the map's claim `claim`.
std::vector<RegionPoint> region_points(const CaseResults& results, const Claim& claim);

/// The verdict on the map's claim `claim`, counted over `results.sweep`'s points; "not
/// measured" when the map did not run.
ClaimVerdict judge_region_claim(const CaseResults& results, const Claim& claim);

/// Refuses (CaseError at the claim's line) a map's claim on a backend no theory bounds one of
/// the map's axes for (map_theory(): an engine on a spring map, an integrator on contacts),
/// naming what the theories cover.
void require_region_theory(const Scene& scene);

}  // namespace bb
