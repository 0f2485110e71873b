// What a [waves] surface must keep to be run and measured: its points within the position
// limit, and close enough along x to resolve its wave.
#pragma once

#include <string>

#include "model/world.hpp"

namespace bb {

/// The most surface points a [waves] may ask for: a profile, not a mesh.
inline constexpr double kMaxWavePoints = 10000;

/// The most phase between neighbouring surface points, in radians: k h at most 1, with h
/// their spacing along x (about 6.3 points a wavelength). Within it the difference
/// (x_{i+1} - x_i) / h that surface_fold takes follows the surface's own slope,
/// 1 - amplitude k sin(phase), to a factor sin(k h / 2) / (k h / 2) of at least 0.95 on its
/// wave part; past it the points draw a coarser surface than the wave's, and from k h = pi
/// on they alias it (they sample a longer wave, or none at all).
inline constexpr double kMostWavePhaseStep = 1.0;

/// A problem with a [waves] surface, and the key of [waves] it lies in.
struct WaveProblem {
  std::string key;      ///< "" when there is none
  std::string problem;  ///< what is wrong, and what would do
};

/// The first problem of `waves` (its points beyond the position limit, or too far apart to
/// resolve its wave), or none.
WaveProblem wave_problem(const Waves& waves);

}  // namespace bb
