// The plot of turning bodies (seed section 5): for each plotted body that spins, its angle
// and its angular velocity against time at report_dt, every backend over the reference.
// In 2D the angle is the turn about z, unwrapped, and the angular velocity its z part;
// in 3D the angle is how far the body's spin axis at the start (its principal axis
// closest to the initial spin) has tilted from where it started, so a tennis-racket flip
// shows as a swing to 180 degrees and back, and the angular velocity is that axis's
// component of the spin in the body frame, which changes sign at each flip.
#pragma once

#include <string>
#include <vector>

#include "files/file_batch.hpp"
#include "run/results.hpp"

namespace bb {

/// The plotted bodies (the first kPlottedBodies) that turn: a box spinning at the start, a
/// body on a hinge, or one whose flips, spin after a hit or final angle are observed.
std::vector<int> turning_bodies(const Scene& scene);

/// Draws the plot as `name` into `batch`; returns why there is none, else "".
std::string rotation_plot(const CaseResults& results, FileBatch& batch, const std::string& name);

}  // namespace bb
