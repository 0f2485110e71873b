// The stepping loop: one backend, one scene, one dt, sampled on the case's sample grid.
#pragma once

#include "run/results.hpp"

namespace bb {

class TrajectoryWriter;

/// Runs to the end or to divergence. Never throws: an exception inside the backend becomes
/// status Error with its message; missing features become Unsupported. With
/// `judge_stability`, at a dt the stability search begins with (its dt_min or dt_max) the
/// run also judges that trial on its own steps (RunRecord::stability_trial). With `steps`,
/// every body's state at every step (the start included) goes to it, handed to its file at
/// every sample, up to where the run stopped; without, the loop reads no state for it.
RunRecord run_accuracy(const Backend& backend, const Scene& scene, double dt,
                       bool judge_stability = false, TrajectoryWriter* steps = nullptr);

/// The features `scene` needs that `backend` lacks, as "a, b, c"; empty when none.
std::string missing_features(const Backend& backend, const Scene& scene);

}  // namespace bb
