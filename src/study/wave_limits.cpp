#include "study/wave_limits.hpp"

#include <algorithm>
#include <cmath>

#include "model/text.hpp"
#include "study/vector_limits.hpp"

namespace bb {

namespace {

/// Why the points of `w` do not resolve its wave ("" when they do), with the points or the
/// wavenumber that would.
std::string resolution_problem(const Waves& w) {
  const double length = w.to - w.from;
  const double spacing = length / (w.points - 1);
  const double step = w.wavenumber * spacing;
  if (step <= kMostWavePhaseStep) return "";
  // k (to - from) / (points - 1) <= 1 asks for points >= k (to - from) + 1.
  const double points = std::ceil(w.wavenumber * length / kMostWavePhaseStep) + 1.0;
  const std::string more =
      points <= kMaxWavePoints
          ? "at least " + short_number(points) + " points from 'from' to 'to'"
          : "a stretch from 'from' to 'to' of at most " +
                short_number(kMostWavePhaseStep * (kMaxWavePoints - 1) / w.wavenumber) +
                " m (the most " + short_number(kMaxWavePoints) + " points resolve)";
  return "puts neighbouring surface points k h = " + short_number(step) +
         " rad of the wave apart (wavenumber " + short_number(w.wavenumber) + " 1/m, points " +
         short_number(spacing) + " m apart along x): more than " +
         short_number(kMostWavePhaseStep) +
         " rad, so the points do not resolve the wave (from pi rad on they alias it) and "
         "surface_fold, measured between neighbours, would not be the wave's; give " +
         more + ", or a wavenumber of at most " + short_number(kMostWavePhaseStep / spacing) +
         " 1/m";
}

}  // namespace

WaveProblem wave_problem(const Waves& w) {
  // The farthest a point gets: its rest position and the circle's radius, along x and y.
  const Vec3 farthest(std::max(std::abs(w.from), std::abs(w.to)) + w.amplitude,
                      std::abs(w.level) + w.amplitude, 0.0);
  if (const std::string problem = vector_limit_problem(VectorKind::Position, farthest);
      !problem.empty())
    return {"amplitude", "takes the surface's points to a position that " + problem};
  if (const std::string problem = resolution_problem(w); !problem.empty())
    return {"wavenumber", problem};
  return {};
}

}  // namespace bb
