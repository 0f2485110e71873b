// What the runner makes of an engine's interventions (seam/backend.hpp): a reset ends a run
// as diverged at the reset's time, a cap makes it capped; a stability trial of either is not
// stable. The accuracy run and the stability search's own trials read them alike.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "run/results.hpp"
#include "seam/backend.hpp"

namespace bb {

/// The first intervention of `kind` (a copy: `all` is often a temporary), or nullopt.
std::optional<EngineIntervention> intervention_of(const std::vector<EngineIntervention>& all,
                                                  EngineIntervention::Kind kind);

/// When it happened (seconds) in a run at step `dt`: its step count times dt.
double intervention_time(const EngineIntervention& intervention, double dt);

/// The reason a run gives for it: "<what> at t = <T> s: <cause>" for a reset, "<what> from
/// t = <T> s: <cause>" for a cap (without ": <cause>" when the engine gives none).
std::string intervention_reason(const EngineIntervention& intervention, double dt);

/// A stability trial's verdict where the engine intervened: a reset is "diverged", a cap
/// "capped", neither stable, the reason as above; nullopt when it did neither.
std::optional<StabilityTrial> intervened_trial(const std::vector<EngineIntervention>& all,
                                               double dt);

}  // namespace bb
