// Small text helpers for messages.
#pragma once

#include <cmath>
#include <sstream>
#include <string>
#include <vector>

namespace bb {

/// "a, b, c".
inline std::string joined(const std::vector<std::string>& words) {
  std::string out;
  for (const std::string& w : words) out += (out.empty() ? "" : ", ") + w;
  return out;
}

/// A step as people write it: "1/60" when 1/dt is a whole number, else seconds (6 digits).
inline std::string format_dt(double dt) {
  const double rate = 1.0 / dt;
  if (std::abs(rate - std::round(rate)) < 1e-6 * rate)
    return "1/" + std::to_string(std::llround(rate));
  std::ostringstream s;
  s.precision(6);
  s << dt;
  return s.str();
}

}  // namespace bb
