// What every fixed-step backend does as a step begins, before its own solver runs: the
// impulses due at the step's start, in time order, then the forces and torques of the
// force model from the state the step starts in (for an engine: its own current state, the
// way a game adds forces before each step). One copy, used by the course and every engine.
#pragma once

#include <cmath>

#include "physics/state_forces.hpp"

namespace bb {

class StepStart {
 public:
  StepStart(const World& scene, double dt, const ForceOptions& options = {});

  /// Calls `push(impulse)` for each impulse due at the start of the step about to be
  /// taken (its time rounds to that step's start), then counts that step.
  template <class Push>
  void impulses_due(Push&& push) {
    for (; next_ < scene_->impulses.size() &&
           std::llround(scene_->impulses[next_].time / dt_) <= steps_;
         ++next_)
      push(scene_->impulses[next_]);
    ++steps_;
  }

  /// Whether any force or torque acts (else there is nothing to read the state for).
  bool has_loads() const { return !forces_.model().empty(); }
  /// Whether any term gives a torque.
  bool torques() const { return forces_.model().torques(); }
  /// The forces and torques at `state`, one entry per body (zero on fixed bodies).
  const Loads& loads(const State& state) { return forces_.at(state); }

 private:
  const World* scene_;
  double dt_;
  long steps_ = 0;        ///< steps counted; the next one starts at steps_ * dt
  std::size_t next_ = 0;  ///< the first impulse not applied yet
  StateForces forces_;
};

}  // namespace bb
