#include "reference/closed_form.hpp"

#include <gsl/gsl_mode.h>
#include <gsl/gsl_sf_ellint.h>
#include <gsl/gsl_sf_elljac.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace bb::closed_form {

double terminal_speed(double m, double g, double rho, double cd, double a) {
  return std::sqrt(2.0 * m * g / (rho * cd * a));
}

double fall_speed(double vt, double g, double t) {
  return vt * std::tanh(g * t / vt);
}

double fall_distance(double vt, double g, double t) {
  // ln cosh x written as |x| + ln(1 + e^{-2|x|}) - ln 2: cosh overflows past x = 710, which a
  // light body reaches within a second.
  const double x = std::abs(g * t / vt);
  return vt * vt / g * (x + std::log1p(std::exp(-2.0 * x)) - std::log(2.0));
}

double spring_pair_extension(double m1, double m2, double k, double c, double x0, double t) {
  const double mu = m1 * m2 / (m1 + m2);
  const double omega2 = k / mu, half_rate = 0.5 * c / mu;
  const double decay = std::exp(-half_rate * t);
  const double d = omega2 - half_rate * half_rate;
  // From rest: x(0) = x0, x'(0) = 0, in each of the three damping regimes.
  if (d > 0.0) {
    const double w = std::sqrt(d);
    return x0 * decay * (std::cos(w * t) + half_rate / w * std::sin(w * t));
  }
  if (d == 0.0) return x0 * decay * (1.0 + half_rate * t);
  // Overdamped: two decaying exponentials, rates r1 > r2 (written so nothing overflows).
  const double s = std::sqrt(-d), r1 = -half_rate + s, r2 = -half_rate - s;
  return x0 * (r2 * std::exp(r1 * t) - r1 * std::exp(r2 * t)) / (r2 - r1);
}

double spring_pair_largest_extension(double m1, double m2, double k, double c, double v0) {
  const double mu = m1 * m2 / (m1 + m2);
  const double g = 0.5 * c / mu, w = std::sqrt(k / mu - g * g);
  const double t = std::atan2(w, g) / w;
  return v0 / w * std::exp(-g * t) * std::sin(w * t);
}

double spring_pair_period(double m1, double m2, double k) {
  return 2.0 * std::numbers::pi * std::sqrt(m1 * m2 / (m1 + m2) / k);
}

Eigen::Vector3d free_top_spin(const Eigen::Vector3d& inertia, const Eigen::Vector3d& spin0,
                              double t) {
  // Axes 1, 2, 3 by decreasing moment.
  int order[3] = {0, 1, 2};
  std::sort(order, order + 3, [&](int a, int b) { return inertia[a] > inertia[b]; });
  const double i1 = inertia[order[0]], i2 = inertia[order[1]], i3 = inertia[order[2]];
  const double w1 = spin0[order[0]], w2 = spin0[order[1]], w3 = spin0[order[2]];
  if (!(i1 > i2 && i2 > i3)) throw std::domain_error("free_top_spin: moments not distinct");
  const double energy2 = i1 * w1 * w1 + i2 * w2 * w2 + i3 * w3 * w3;  // 2 E
  const double l2 = i1 * i1 * w1 * w1 + i2 * i2 * w2 * w2 + i3 * i3 * w3 * w3;
  if (!(l2 > energy2 * i2)) throw std::domain_error("free_top_spin: needs L^2 > 2 E I_middle");
  // omega_1 = s1 A1 dn(u), omega_2 = -s1 A2 sn(u), omega_3 = A3 cn(u), u = rate t + u0: these
  // signs make the three satisfy Euler's equations.
  const double a1 = std::sqrt((l2 - energy2 * i3) / (i1 * (i1 - i3)));
  const double a2 = std::sqrt((energy2 * i1 - l2) / (i2 * (i1 - i2)));
  const double a3 = std::sqrt((energy2 * i1 - l2) / (i3 * (i1 - i3)));
  const double rate = std::sqrt((i1 - i2) * (l2 - energy2 * i3) / (i1 * i2 * i3));
  const double m = (i2 - i3) * (energy2 * i1 - l2) / ((i1 - i2) * (l2 - energy2 * i3));
  const double s1 = w1 < 0.0 ? -1.0 : 1.0;
  // u0 from its amplitude phi0: sn = sin(phi0), cn = cos(phi0).
  const double phi0 = std::atan2(a2 > 0.0 ? -s1 * w2 / a2 : 0.0, a3 > 0.0 ? w3 / a3 : 1.0);
  const double u0 = gsl_sf_ellint_F(phi0, std::sqrt(m), GSL_PREC_DOUBLE);
  double sn = 0.0, cn = 0.0, dn = 0.0;
  gsl_sf_elljac_e(rate * t + u0, m, &sn, &cn, &dn);
  Eigen::Vector3d out;
  out[order[0]] = s1 * a1 * dn;
  out[order[1]] = -s1 * a2 * sn;
  out[order[2]] = a3 * cn;
  return out;
}

}  // namespace bb::closed_form
