// Numbers as the metrics write them into reasons and notes: a few significant digits.
#pragma once

#include <cstdio>
#include <string>

namespace bb {

/// `x` with `digits` significant digits, as printf's "%.*g" writes it.
inline std::string short_number(double x, int digits = 3) {
  char buffer[40];
  std::snprintf(buffer, sizeof buffer, "%.*g", digits, x);
  return buffer;
}

}  // namespace bb
