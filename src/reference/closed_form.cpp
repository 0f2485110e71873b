#include "reference/closed_form.hpp"

#include <cmath>
#include <numbers>

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

double spring_pair_period(double m1, double m2, double k) {
  return 2.0 * std::numbers::pi * std::sqrt(m1 * m2 / (m1 + m2) / k);
}

}  // namespace bb::closed_form
