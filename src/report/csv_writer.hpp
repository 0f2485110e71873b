// Results as CSV: one tidy row per (backend, dt), with a header.
#pragma once

#include <string>

#include "run/results.hpp"

namespace bb {

std::string results_csv(const CaseResults& results);

}  // namespace bb
