#include "course/integrators.hpp"

#include <stdexcept>

namespace bb::course {

namespace {

/// Seed section 1, the "middle ball" of Three beachballs 1: position moves first, with
/// the old velocity, then the velocity takes the acceleration. Gains energy under gravity.
void explicit_euler(PointState& s, double dt, const AccelerationFn& acceleration, Workspace& w) {
  acceleration(s.x, s.v, w.a0);
  for (std::size_t i = 0; i < s.x.size(); ++i) {
    s.x[i] += s.v[i] * dt;
    s.v[i] += w.a0[i] * dt;
  }
}

/// Seed section 1, the left and right balls: velocity takes the acceleration first, then
/// the position moves with the new velocity (symplectic, or semi-implicit, Euler).
void semi_implicit_euler(PointState& s, double dt, const AccelerationFn& acceleration,
                         Workspace& w) {
  acceleration(s.x, s.v, w.a0);
  for (std::size_t i = 0; i < s.x.size(); ++i) {
    s.v[i] += w.a0[i] * dt;
    s.x[i] += s.v[i] * dt;
  }
}

/// Velocity Verlet. Drag and Magnus depend on velocity, so the end-of-step acceleration
/// needs a velocity that is not known yet: it is evaluated at the new position and at the
/// predicted velocity v + a0 dt, and the velocity then takes the mean of both
/// accelerations. The prediction is accurate to O(dt^2), which keeps the method second
/// order; with position-only forces it reduces to textbook velocity Verlet.
void velocity_verlet(PointState& s, double dt, const AccelerationFn& acceleration, Workspace& w) {
  acceleration(s.x, s.v, w.a0);
  for (std::size_t i = 0; i < s.x.size(); ++i) {
    w.x1[i] = s.x[i] + s.v[i] * dt + w.a0[i] * (0.5 * dt * dt);
    w.v1[i] = s.v[i] + w.a0[i] * dt;
  }
  acceleration(w.x1, w.v1, w.a1);
  for (std::size_t i = 0; i < s.x.size(); ++i) {
    s.x[i] = w.x1[i];
    s.v[i] += (w.a0[i] + w.a1[i]) * (0.5 * dt);
  }
}

/// Classic fourth-order Runge-Kutta on (x, v); the stages' dx/dt is their trial velocity.
void rk4(PointState& s, double dt, const AccelerationFn& acceleration, Workspace& w) {
  const std::size_t n = s.x.size();
  const double h = 0.5 * dt;
  // Stage 1 at the start; stage 2 at the midpoint reached with stage 1's slopes.
  acceleration(s.x, s.v, w.a0);
  for (std::size_t i = 0; i < n; ++i) {
    w.x1[i] = s.x[i] + s.v[i] * h;
    w.v1[i] = s.v[i] + w.a0[i] * h;
  }
  acceleration(w.x1, w.v1, w.a1);
  // Stage 3 at the midpoint reached with stage 2's slopes.
  for (std::size_t i = 0; i < n; ++i) {
    w.x1[i] = s.x[i] + w.v1[i] * h;
    w.v2[i] = s.v[i] + w.a1[i] * h;
  }
  acceleration(w.x1, w.v2, w.a2);
  // Stage 4 at the end reached with stage 3's slopes.
  for (std::size_t i = 0; i < n; ++i) {
    w.x1[i] = s.x[i] + w.v2[i] * dt;
    w.v3[i] = s.v[i] + w.a2[i] * dt;
  }
  acceleration(w.x1, w.v3, w.a3);
  for (std::size_t i = 0; i < n; ++i) {
    s.x[i] += (s.v[i] + 2.0 * w.v1[i] + 2.0 * w.v2[i] + w.v3[i]) * (dt / 6.0);
    s.v[i] += (w.a0[i] + 2.0 * w.a1[i] + 2.0 * w.a2[i] + w.a3[i]) * (dt / 6.0);
  }
}

}  // namespace

StepFn integrator(const std::string& name) {
  if (name == "explicit-euler") return explicit_euler;
  if (name == "semi-implicit-euler") return semi_implicit_euler;
  if (name == "velocity-verlet") return velocity_verlet;
  if (name == "rk4") return rk4;
  throw std::invalid_argument("unknown integrator '" + name + "'");
}

}  // namespace bb::course
