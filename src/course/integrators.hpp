// The time-stepping rules of the course text, section 1 ("Movement in discrete time")
// and the demo "Three beachballs 1", plus the two higher-order methods it points to.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "model/vec3.hpp"

namespace bb::course {

/// Positions and velocities of every body, stepped together.
struct PointState {
  std::vector<Vec3> x;  ///< metres
  std::vector<Vec3> v;  ///< metres per second
};

/// a(x, v) for every body.
using AccelerationFn = std::function<void(const std::vector<Vec3>& x, const std::vector<Vec3>& v,
                                          std::vector<Vec3>& a)>;

/// Buffers an integrator reuses from step to step, so a step allocates nothing.
struct Workspace {
  std::vector<Vec3> a0, a1, a2, a3, x1, v1, v2, v3;
  void resize(std::size_t n) {
    for (auto* b : {&a0, &a1, &a2, &a3, &x1, &v1, &v2, &v3}) b->resize(n);
  }
};

/// One step of `dt` seconds with the named integrator.
using StepFn = void (*)(PointState& s, double dt, const AccelerationFn& acceleration, Workspace& w);

/// The stepping rule called `name` ("explicit-euler", ...); throws std::invalid_argument.
StepFn integrator(const std::string& name);

}  // namespace bb::course
