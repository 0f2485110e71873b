// How numbers look in tables: steps as 1/60 s, errors in three significant digits.
#pragma once

#include <optional>
#include <string>

#include "scene/text.hpp"

namespace bb {

/// Three significant digits, "-" when absent.
std::string format_value(std::optional<double> value);
/// A cost in ns per step, "-" when absent.
std::string format_ns(std::optional<double> ns);

}  // namespace bb
