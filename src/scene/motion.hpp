// The scene's equations of motion between contacts: gravity, air forces and springs. The
// course methods and the reference integrate these same equations; they differ only in how
// they step through time.
#pragma once

#include <vector>

#include "scene/air_forces.hpp"
#include "scene/scene.hpp"
#include "scene/spring_forces.hpp"
#include "scene/state.hpp"

namespace bb {

/// The equations set up once per run, so that evaluating them allocates nothing.
class EquationsOfMotion {
 public:
  explicit EquationsOfMotion(const Scene& scene);
  /// Linear acceleration (m/s^2) of every body at positions `x` and velocities `v`; `omega`
  /// is each body's angular velocity, `q` its orientation (for the wind on a panel). Fixed
  /// bodies get zero. `out` must have one entry per body.
  void accelerations(const std::vector<Vec3>& x, const std::vector<Vec3>& v,
                     const std::vector<Vec3>& omega, const std::vector<Quat>& q,
                     std::vector<Vec3>& out) const;
  const SpringNetwork& springs() const { return springs_; }

 private:
  const Scene& scene_;
  SpringNetwork springs_;
  std::vector<double> inverse_mass_;  ///< 1/kg, 0 for fixed bodies
  std::vector<int> panels_;           ///< bodies with a wind_force
};

// Inline, so the course's step inlines the whole force evaluation.
inline void EquationsOfMotion::accelerations(const std::vector<Vec3>& x, const std::vector<Vec3>& v,
                                             const std::vector<Vec3>& omega,
                                             const std::vector<Quat>& q,
                                             std::vector<Vec3>& out) const {
  const std::size_t n = scene_.bodies.size();
  // Forces first (springs act on both ends), then each body's acceleration from its force.
  for (std::size_t i = 0; i < n; ++i) out[i].setZero();
  if (!springs_.empty()) add_spring_forces(springs_, x.data(), v.data(), out.data());
  if (scene_.air)
    for (std::size_t i = 0; i < n; ++i)
      out[i] += air_force(scene_, scene_.bodies[i], v[i], omega[i]);
  for (int i : panels_) out[i] += panel_wind_force(scene_.bodies[i], q[i]);
  for (std::size_t i = 0; i < n; ++i)
    out[i] =
        inverse_mass_[i] == 0.0 ? Vec3::Zero() : Vec3(scene_.gravity + out[i] * inverse_mass_[i]);
}

/// Kinetic energy (J) of one body, its spin's part included; zero for a fixed body.
double kinetic_energy(const Body& body, const BodyState& state);

/// Angular momentum (N m s) of one body about the world's origin: r x m v + J omega.
Vec3 angular_momentum(const Body& body, const BodyState& state);

/// Total mechanical energy (J): kinetic, rotational, gravitational (zero at the origin) and
/// the springs' potential energy.
double total_energy(const Scene& scene, const State& state);

/// The state the case file describes at t = 0.
State initial_state(const Scene& scene);

}  // namespace bb
