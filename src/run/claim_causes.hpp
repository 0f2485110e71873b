// Known causes of a claim's verdict, computed from the scene and what a backend was given:
// a verdict other than "holds" says why where the harness knows it, so that a reader does
// not take an engine's documented limit for a fault of the text or of the engine.
#pragma once

#include <string>

#include "run/results.hpp"

namespace bb {

/// Why `run`'s backend may not reproduce what the scene's physics does, when a known limit
/// applies to this scene, or "". Known: an engine with one friction coefficient, given
/// friction_kinetic, on a slope between atan(mu_k) and atan(mu_s), where Coulomb's static
/// friction holds a body at rest and the engine lets it slide.
std::string known_cause(const Scene& scene, const RunRecord& run);

}  // namespace bb
