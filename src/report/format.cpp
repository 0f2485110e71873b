#include "report/format.hpp"

#include <fmt/format.h>

#include <cmath>

namespace bb {

std::string format_dt(double dt) {
  const double rate = 1.0 / dt;
  if (std::abs(rate - std::round(rate)) < 1e-6 * rate)
    return fmt::format("1/{}", std::llround(rate));
  return fmt::format("{:.6g}", dt);
}

std::string format_value(std::optional<double> value) {
  if (!value) return "-";
  return fmt::format("{:.3g}", *value);
}

std::string format_ns(std::optional<double> ns) {
  if (!ns) return "-";
  return *ns >= 100.0 ? fmt::format("{:.0f}", *ns) : fmt::format("{:.3g}", *ns);
}

}  // namespace bb
