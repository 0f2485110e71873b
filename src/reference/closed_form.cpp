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
  return vt * vt / g * std::log(std::cosh(g * t / vt));
}

}  // namespace bb::closed_form
