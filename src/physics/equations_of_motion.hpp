// The scene's equations of motion between contacts for the course methods: gravity plus the
// force model's forces over each body's mass. The course integrates these; the reference
// uses the same force model in its own state layout.
#pragma once

#include <vector>

#include "physics/force_model.hpp"

namespace bb {

/// The equations set up once per run, so that evaluating them allocates nothing.
class EquationsOfMotion {
 public:
  explicit EquationsOfMotion(const World& scene);
  /// Linear acceleration (m/s^2) of every body at positions `x` and velocities `v`; `omega`
  /// is each body's angular velocity, `q` its orientation. Fixed bodies get zero. `out`
  /// must have one entry per body. The torques at that state are kept (torques()).
  void accelerations(const std::vector<Vec3>& x, const std::vector<Vec3>& v,
                     const std::vector<Vec3>& omega, const std::vector<Quat>& q,
                     std::vector<Vec3>& out) const {
    forces_.evaluate({x.data(), v.data(), q.data(), omega.data()}, out.data(), torque_.data());
    const Vec3& g = forces_.gravity();
    for (std::size_t i = 0; i < out.size(); ++i)
      out[i] = inverse_mass_[i] == 0.0 ? Vec3::Zero() : Vec3(g + out[i] * inverse_mass_[i]);
  }
  /// The torques (N m, world frame) at the state of the last accelerations() call.
  const std::vector<Vec3>& torques() const { return torque_; }
  const ForceModel& forces() const { return forces_; }

 private:
  ForceModel forces_;
  std::vector<double> inverse_mass_;  ///< 1/kg, 0 for fixed bodies
  mutable std::vector<Vec3> torque_;  ///< scratch: the last evaluation's torques
};

}  // namespace bb
