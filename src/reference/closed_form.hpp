// Closed forms the reference is checked against.
#pragma once

#include <Eigen/Core>

namespace bb::closed_form {

/// Terminal speed (m/s) of a body of mass m (kg), drag coefficient cd and frontal area a
/// (m^2) in air of density rho (kg/m^3) under gravity g (m/s^2): sqrt(2 m g / (rho cd a)).
double terminal_speed(double m, double g, double rho, double cd, double a);

/// Speed (m/s) after falling from rest for t seconds: vt tanh(g t / vt).
double fall_speed(double vt, double g, double t);

/// Distance (m) fallen from rest in t seconds: vt^2 / g ln cosh(g t / vt).
double fall_distance(double vt, double g, double t);

/// Extension (m) at time t of two masses on a spring, released at rest with extension x0:
/// the relative coordinate is a damped oscillator of reduced mass mu = m1 m2 / (m1 + m2),
/// x'' = -(k / mu) x - (c / mu) x'. Underdamped, critically damped or overdamped.
double spring_pair_extension(double m1, double m2, double k, double c, double x0, double t);

/// The largest extension (m) of two masses on a spring that start at its rest length,
/// moving apart along it at relative speed v0 (m/s), underdamped: its first peak,
/// v0 / w_d exp(-g t*) sin(w_d t*), g = c / (2 mu), w_d = sqrt(k / mu - g^2), at
/// t* = atan(w_d / g) / w_d (pi / (2 w_d) undamped).
double spring_pair_largest_extension(double m1, double m2, double k, double c, double v0);

/// Period (s) of the undamped pair: 2 pi sqrt(mu / k).
double spring_pair_period(double m1, double m2, double k);

/// Spin (rad/s, in the body's principal frame) at time t of a free rigid body with principal
/// moments `inertia` (kg m^2, distinct) that started with body-frame spin `spin0`: Euler's
/// torque-free equations solved by Jacobi's elliptic functions (Landau and Lifshitz,
/// Mechanics, section 37). For a body turning about the largest axis or near the middle
/// one from that side (L^2 > 2 E I_middle); throws std::domain_error otherwise.
Eigen::Vector3d free_top_spin(const Eigen::Vector3d& inertia, const Eigen::Vector3d& spin0,
                              double t);

}  // namespace bb::closed_form
