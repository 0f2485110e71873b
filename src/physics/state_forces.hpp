// The force model evaluated at a runner's State (one BodyState per body): what an engine
// adapter reads from its bodies before a step, and what an observable reads from a sample.
#pragma once

#include <vector>

#include "model/state.hpp"
#include "physics/force_model.hpp"

namespace bb {

class StateForces {
 public:
  explicit StateForces(const World& scene, const ForceOptions& options = {});
  /// The forces and torques at `state`, one entry per body (zero on fixed bodies); nothing
  /// allocates.
  const Loads& at(const State& state);
  /// `state` as the arrays the force model reads (valid until the next call).
  BodyStates view(const State& state);
  const ForceModel& model() const { return model_; }

 private:
  ForceModel model_;
  std::vector<Vec3> x_, v_, w_;  ///< the state as arrays, for the force model
  std::vector<Quat> q_;
  Loads loads_;
};

}  // namespace bb
