// Verdicts on the course text's sentences ([[claim]] in a case file): each claim compared,
// for each backend it names (every one for "*"), at every dt of that backend's sweep. A
// claim that holds at the small steps and fails at the large ones says from which dt it
// holds: a finding, with its numbers.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "run/results.hpp"

namespace bb {

/// One backend's verdict on a claim.
struct ClaimVerdict {
  std::string backend;
  /// "holds", "fails", "holds for dt <= <X>", "holds at dt <list> only", or
  /// "not measured (<why>)"; with "; diverged at dt <list> s" where runs blew up (they
  /// have no numbers to judge).
  std::string verdict;
  std::optional<double> left, right;  ///< the two numbers at report_dt (the reference: its own)
};

struct ClaimResult {
  const Claim* claim = nullptr;
  std::vector<ClaimVerdict> verdicts;
};

/// Every claim of `results.scene` judged on `results`' runs.
std::vector<ClaimResult> judge_claims(const CaseResults& results);

/// Whether `left op right` holds; "~" means within `tolerance`.
bool claim_holds(const std::string& op, double left, double right, double tolerance);

}  // namespace bb
