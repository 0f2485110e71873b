// The force model's derivative checked against finite differences: the check the force
// terms' tests share (a sail, a hull, a wind panel).
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <functional>
#include <vector>

#include "model/motion.hpp"
#include "physics/force_model.hpp"

namespace bb::test {

/// The force model's d(force on body 0) / d(its velocity) at `s`, column by column, against
/// central differences of `force_at(velocity)` (steps of 1e-6 m/s): each column within
/// `tolerance` times max(1, the column's size).
inline void expect_velocity_derivative_matches(const Scene& scene, const State& s,
                                               const std::function<Vec3(const Vec3&)>& force_at,
                                               double tolerance) {
  std::vector<Vec3> x{s[0].position}, v{s[0].velocity}, w{s[0].angular_velocity};
  std::vector<Quat> q{s[0].orientation};
  ForceJacobian jacobian;
  ForceModel(scene).jacobian({x.data(), v.data(), q.data(), w.data()}, jacobian);
  const double h = 1e-6;
  for (int c = 0; c < 3; ++c) {
    Vec3 up = v[0], down = v[0];
    up[c] += h, down[c] -= h;
    const Vec3 numeric = (force_at(up) - force_at(down)) / (2.0 * h);
    Vec3 analytic = Vec3::Zero();
    for (const JacobianBlock& b : jacobian.blocks())
      if (b.body == 0 && b.by_body == 0 && b.wrt == Wrt::Velocity) analytic += b.value.col(c);
    EXPECT_LT((analytic - numeric).norm(), tolerance * std::max(1.0, numeric.norm()))
        << "axis " << c;
  }
}

}  // namespace bb::test
