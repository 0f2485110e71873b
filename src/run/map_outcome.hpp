// A run's outcome at a point of a map (two [[sweep]]s), as the map's cells and its claims
// classify it: ok, past the first [[sweep]]'s onset, diverged, unsupported, failed, or not run.
#pragma once

#include <string>

#include "run/results.hpp"

namespace bb {

enum class MapOutcome { Ok, PastOnset, Diverged, Unsupported, Failed, Absent };

/// The outcome's name, as the legend and the page say it.
std::string map_outcome_name(MapOutcome outcome);

/// `run`'s outcome: its status; an ok run whose value of the first [[sweep]]'s `onset` is
/// above `onset_above` is past the onset (a spring's stretch grown tenfold: exploded).
MapOutcome map_outcome(const Scene& scene, const RunRecord* run);

/// Whether `outcome` is one a run that ran to a verdict has (ok, past the onset, diverged),
/// one another can be compared with or a claim judged on; not unsupported, failed or absent.
bool ran_to_an_outcome(MapOutcome outcome);

}  // namespace bb
