// Small text helpers for messages.
#pragma once

#include <cmath>
#include <cstdio>
#include <cstdlib>
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

/// Characters in UTF-8 `s` (continuation bytes do not count).
inline std::size_t character_count(const std::string& s) {
  std::size_t n = 0;
  for (unsigned char c : s) n += (c & 0xC0) != 0x80;
  return n;
}

/// True when `s` is not empty and every character is a-z, 0-9, '_', or one of `extra`;
/// `upper` allows A-Z too.
inline bool is_name(const std::string& s, bool upper, const char* extra = "") {
  if (s.empty()) return false;
  for (char c : s) {
    const bool ok = (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_' ||
                    (upper && c >= 'A' && c <= 'Z') ||
                    (c != '\0' && std::string(extra).find(c) != std::string::npos);
    if (!ok) return false;
  }
  return true;
}

/// A number for a message, as a stream writes it (6 significant digits).
inline std::string short_number(double x) {
  std::ostringstream s;
  s << x;
  return s.str();
}

/// `x` with `digits` significant digits, as printf's "%.*g" writes it (the metrics'
/// reasons and notes).
inline std::string significant_digits(double x, int digits = 3) {
  char buffer[40];
  std::snprintf(buffer, sizeof buffer, "%.*g", digits, x);
  return buffer;
}

/// `x` in the fewest significant digits that read back as the same double (0.50000001, not
/// 0.5): a number the user wrote, said back.
inline std::string shortest_number(double x) {
  for (int digits = 6; digits < 17; ++digits) {
    const std::string text = significant_digits(x, digits);
    if (std::strtod(text.c_str(), nullptr) == x) return text;
  }
  return significant_digits(x, 17);
}

/// `x` exactly: 17 significant digits, which read back as the same double.
inline std::string exact_number(double x) {
  return significant_digits(x, 17);
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
