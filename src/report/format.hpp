// How numbers look in tables: steps as 1/60 s, errors in three significant digits.
#pragma once

#include <optional>
#include <string>

namespace bb {

/// "1/60" when 1/dt is a whole number, else the seconds with 6 significant digits.
std::string format_dt(double dt);
/// Three significant digits, "-" when absent.
std::string format_value(std::optional<double> value);
/// A cost in ns per step, "-" when absent.
std::string format_ns(std::optional<double> ns);

}  // namespace bb
