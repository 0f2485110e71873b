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

/// What a verdict says, for counting: a claim that holds at every dt judged, at some only,
/// at none, or that has nothing to judge.
enum class VerdictKind { Holds, Partial, Fails, NotMeasured };

/// One backend's verdict on a claim.
struct ClaimVerdict {
  std::string backend;
  /// "holds", "fails", "holds for dt <= <X> s", "holds for dt >= <X> s", "holds at dt
  /// <list> s only", or "not measured (<why>)"; with "; diverged at dt <list> s" where runs
  /// blew up and the claim does not say what that means (they have no numbers to judge),
  /// or "; diverged at dt <list> s, counted as holding" ("as failing") where it does.
  std::string verdict;
  VerdictKind kind = VerdictKind::NotMeasured;
  std::vector<double> diverged;  ///< the dts whose runs diverged, largest first
  bool diverged_judged = false;  ///< the claim's `diverged` made them count
  /// A known cause of a verdict other than "holds", computed from the scene and the
  /// backend's settings (claim_causes.hpp); empty when none is known.
  std::string cause;
  std::optional<double> left, right;  ///< the two numbers at report_dt (the reference: its own)
};

struct ClaimResult {
  const Claim* claim = nullptr;
  std::vector<ClaimVerdict> verdicts;
};

/// Every claim of `results.scene` judged on `results`' runs.
std::vector<ClaimResult> judge_claims(const CaseResults& results);

/// Whether the reference gets a verdict on `claim`: where the claim names it, or says "*"
/// about a quantity the reference has of its own (not an error, which is measured against
/// it, nor a comparison with the reference's own value).
bool judges_the_reference(const Claim& claim);

/// Whether `left op right` holds; "~" means within `tolerance`.
bool claim_holds(const std::string& op, double left, double right, double tolerance);

/// How a claim counts in the ledger's headline.
enum class ClaimStanding {
  Holds,    ///< holds for every backend, at every dt judged
  Fails,    ///< fails, or holds only in part, for some backend
  Neither,  ///< no fail, but some backend not measured or with runs that diverged unjudged
};
ClaimStanding claim_standing(const ClaimResult& claim);

}  // namespace bb
