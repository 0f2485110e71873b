// The registry of force terms: every force the harness knows, in the order they are summed.
// A new force is one file in physics/ (its term and factory) plus one line in
// force_terms.cpp.
#pragma once

#include <string>
#include <vector>

#include "physics/force_term.hpp"

namespace bb {

struct ForceTermEntry {
  std::string name;  ///< what the force is, for messages and listings
  ForceTermFactory make;
};

/// Every registered term, in summation order (fixed, so every backend adds the same
/// floating-point sums).
const std::vector<ForceTermEntry>& force_terms();

}  // namespace bb
