// One stability trial's judgement, fed a run's state at every step: its energy's growth
// after the last impulse (energy_growth.hpp) and divergence (divergence.hpp). The search's
// own trial (stability.hpp) and an accuracy run at the same step (which then need not be
// run twice) feed it alike.
#pragma once

#include <optional>
#include <string>

#include "metrics/energy_growth.hpp"
#include "model/state.hpp"
#include "physics/energy.hpp"
#include "run/divergence.hpp"
#include "run/results.hpp"
#include "study/scene.hpp"

namespace bb {

/// The fewest steps a stability trial takes, past the case's duration when it has fewer.
inline constexpr long kMinTrialSteps = 1000;

class StabilityWatch {
 public:
  /// A trial of `scene` at `dt` from the state `start` at t = 0, `steps` steps long.
  StabilityWatch(const Scene& scene, double dt, const State& start, long steps);
  /// Steps a trial of `scene` at `dt` takes: the whole duration, and at least
  /// kMinTrialSteps (growth slow enough to stay small within a few dozen steps is not
  /// stability), within the cap every run keeps to.
  static long trial_steps(const Scene& scene, double dt);
  /// Steps the trial takes: the whole duration.
  long steps() const { return steps_; }
  /// The state after step n (1 to steps(), in order); false once the verdict is in.
  bool observe(long n, const State& state);
  /// The verdict, once every step was observed or the run diverged; nullopt before.
  std::optional<StabilityTrial> verdict() const;

 private:
  const Scene& scene_;
  DivergenceBounds bounds_;
  EnergyMeter energy_;
  long steps_ = 0;
  long settled_ = 0;  ///< steps before the energy is judged: up to the last impulse
  long judged_ = 0;
  long windows_ = 0;
  long observed_ = 0;
  double e0_ = 0.0;
  double largest_rise_ = 0.0;
  EnergyHistory history_;
  std::optional<std::string> diverged_;
};

}  // namespace bb
