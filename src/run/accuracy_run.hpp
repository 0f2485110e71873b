// The stepping loop: one backend, one scene, one dt, sampled on the case's sample grid.
#pragma once

#include "run/results.hpp"

namespace bb {

/// Runs to the end or to divergence. Never throws: an exception inside the backend becomes
/// status Error with its message; missing features become Unsupported.
RunRecord run_accuracy(const Backend& backend, const Scene& scene, double dt);

/// The features `scene` needs that `backend` lacks, as "a, b, c"; empty when none.
std::string missing_features(const Backend& backend, const Scene& scene);

}  // namespace bb
