#include "reference/closed_form.hpp"

#include <cmath>

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

}  // namespace bb::closed_form
