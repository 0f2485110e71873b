// The reference's largest values over time, found between its steps: the springs' stretch
// and each body's overlap with what it touches. A fixed-step run sees these at its steps;
// the reference's steps are long and its samples longer still, so it watches every span
// its solver crosses and locates each peak there on the solution itself.
#pragma once

#include <optional>
#include <vector>

#include "model/contact_pairs.hpp"
#include "model/peaks.hpp"
#include "model/world.hpp"
#include "observe/event_watches.hpp"
#include "reference/hybrid_integrator.hpp"
#include "seam/event_trace.hpp"

namespace bb {

class PeakWatch : public SpanWatcher {
 public:
  /// Watches what `scene`'s observables ask for (`events`): max_stretch (every spring with
  /// a rest length) and max_penetration (every contact pair of the observed bodies). `y0`:
  /// the state at t = 0, which counts too.
  PeakWatch(const World& scene, const EventWatches& events, const std::vector<double>& y0);
  /// Whether anything is watched at all.
  bool active() const { return stretch_ || !pairs_.empty(); }
  /// Each spring's stretch at the span's end; between its ends, where a spring's stretch
  /// turns from growing to shrinking and the cubic through the ends says it may beat the
  /// largest yet, the turning point is located on the re-integrated solution (Illinois'
  /// regula falsi on the stretch's rate, to 1e-12 s) and its value taken. The overlaps at
  /// the span's ends (an exact solve has none beyond the event tolerance's).
  void span(HybridIntegrator& integrator, double t0, const double* y0, double t1,
            const double* y1) override;
  /// Writes max_stretch and the observed bodies' max_penetration into `trace`.
  void fill(EventTrace& trace) const;

 private:
  /// The stretch of spring k (an index into springs_) at state y.
  Stretch stretch(std::size_t k, const double* y) const;
  /// Each watched pair's overlap at state y, into penetration_.
  void overlaps(const double* y);
  /// The peak of spring k's stretch within (t0, t1), where its rate turns from r0 > 0 to
  /// r1 < 0: the largest value seen while locating where the rate is zero.
  double locate_peak(HybridIntegrator& integrator, std::size_t k, double t0, double r0, double t1,
                     double r1);

  const World& scene_;
  bool stretch_ = false;             ///< max_stretch is observed
  std::vector<int> springs_;         ///< the springs with a rest length
  double max_stretch_ = 0.0;         ///< as the step observer's: never below 0
  std::vector<ContactPair> pairs_;   ///< the pairs of bodies whose overlap is observed
  std::vector<double> penetration_;  ///< per body, metres
  std::vector<double> probe_;
};

}  // namespace bb
