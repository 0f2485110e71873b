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

std::string format_vector(const Vec3& v, int dims) {
  return dims == 2 ? fmt::format("({:g}, {:g})", v.x(), v.y())
                   : fmt::format("({:g}, {:g}, {:g})", v.x(), v.y(), v.z());
}

}  // namespace bb
