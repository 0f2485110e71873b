#include "study/case_limits.hpp"

#include <sstream>

#include "study/case_error.hpp"
#include "study/load_parts.hpp"

namespace bb {

using load::show;

double contact_pair_count(const CaseSize& size) {
  if (!size.all_pairs) return size.named_pairs;
  return size.bodies * (size.bodies - 1.0) / 2.0 -
         size.fixed_bodies * (size.fixed_bodies - 1.0) / 2.0;
}

void check_case_size(const std::string& file, const CaseSize& size) {
  const auto fail = [&](int line, const std::string& problem) {
    throw CaseError(file, line, problem);
  };
  const double bodies = size.bodies;
  const double samples = size.duration / size.sample;
  if (bodies > kMaxBodies)
    fail(size.case_line,
         "the case has " + show(bodies) + " bodies; beachball runs at most " + show(kMaxBodies));
  if (samples > kMaxSamples)
    fail(size.sample_line, "'duration' / 'sample' gives " + show(samples) + " samples; at most " +
                               show(kMaxSamples) + " are kept per run");
  if (samples * bodies > kMaxBodySamples)
    fail(size.sample_line, show(samples) + " samples of " + show(bodies) +
                               " bodies is more than the " + show(kMaxBodySamples) +
                               " body-samples a run keeps; sample less often or shorten the run");
  const double pairs = contact_pair_count(size);
  if (pairs > kMaxContactPairs)
    fail(size.contact_line, "[[contact]] [\"*\"] among " + show(bodies) + " bodies makes " +
                                show(pairs) + " contact pairs; at most " + show(kMaxContactPairs) +
                                " can be checked at every step (name the pairs that touch)");
  // What one step advances: every body, spring and pair that may touch.
  const double per_step = bodies + size.springs + pairs;
  double work = 0.0;
  for (double step : size.dt) {
    const double steps = size.duration / step;
    if (steps > kMaxStepsPerRun)
      fail(size.dt_line, "'dt' " + show(step) + " s over " + show(size.duration) + " s is " +
                             show(steps) + " steps; a run may take at most " +
                             show(kMaxStepsPerRun));
    work += steps * per_step;
  }
  if (work > kMaxSweepWork)
    fail(size.dt_line,
         "the dt sweep would advance bodies, springs and contact pairs " + show(work) +
             " times per backend (more than " + show(kMaxSweepWork) +
             ", hours of work); shorten the duration, drop the finest dt or use fewer bodies");
  // A swept step runs every point at it: the smallest is the most work.
  const double sweep_step = size.sweep_least_dt > 0.0 ? size.sweep_least_dt : size.report_dt;
  const double sweep_work = size.sweep_points * size.duration / sweep_step * per_step;
  if (sweep_work > kMaxSweepWork)
    fail(size.sweep_line, "the [[sweep]] would advance bodies, springs and contact pairs " +
                              show(sweep_work) + " times per backend (" + show(size.sweep_points) +
                              " points of " + show(size.duration / sweep_step) +
                              " steps at its smallest step; more than " + show(kMaxSweepWork) +
                              ", hours of work); take fewer points or a shorter run");
}

}  // namespace bb
