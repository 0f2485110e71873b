#include "report/format.hpp"

#include <fmt/format.h>

#include <cmath>

namespace bb {

std::string format_value(std::optional<double> value) {
  if (!value) return "-";
  return fmt::format("{:.3g}", *value);
}

std::string format_ns(std::optional<double> ns) {
  if (!ns) return "-";
  return *ns >= 100.0 ? fmt::format("{:.0f}", *ns) : fmt::format("{:.3g}", *ns);
}

}  // namespace bb
