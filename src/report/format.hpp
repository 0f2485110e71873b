// How numbers look in tables: steps as 1/60 s, errors in three significant digits.
#pragma once

#include <optional>
#include <string>

#include "model/text.hpp"
#include "model/vec3.hpp"

namespace bb {

/// Three significant digits, "-" when absent.
std::string format_value(std::optional<double> value);
/// A cost in ns per step, "-" when absent.
std::string format_ns(std::optional<double> ns);
/// "(x, y)" in 2D, "(x, y, z)" in 3D, each in its shortest form ({:g}).
std::string format_vector(const Vec3& v, int dims);

}  // namespace bb
