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
/// floating-point sums): the library's own, then any added by a ForceTermRegistration.
const std::vector<ForceTermEntry>& force_terms();

/// Adds a term after the library's own while it lives: a force brought from outside the
/// library (a test's, a program's own) joins every backend, the energy, the divergence bound,
/// the reference's stiffness and the stability theory exactly as a term of physics/ does.
/// Register before any force model is built; one at a time, not from several threads.
class ForceTermRegistration {
 public:
  explicit ForceTermRegistration(ForceTermEntry entry);
  ~ForceTermRegistration();
  ForceTermRegistration(const ForceTermRegistration&) = delete;
  ForceTermRegistration& operator=(const ForceTermRegistration&) = delete;

 private:
  std::string name_;
};

}  // namespace bb
