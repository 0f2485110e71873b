// A claim's verdicts as the results keep them: judged once, after the runs
// (run/claims.hpp), and read by every writer.
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "study/scene.hpp"

namespace bb {

/// What a verdict says, for counting: a claim that holds at every dt judged, at some only,
/// at none, or that has nothing to judge.
enum class VerdictKind { Holds, Partial, Fails, NotMeasured };

/// A map's claim (region), counted over the map's points: those judged and those of them
/// where it held, and those not judged: within the margin of the boundary, on a side the
/// claim does not state ("any"), where the backend has no outcome (unsupported, failed, not
/// run) or where the theory gives no step.
struct RegionCounts {
  int judged = 0;
  int held = 0;
  int within_margin = 0;
  int unclaimed = 0;
  int no_outcome = 0;
  int no_theory = 0;
  /// The points where it failed: (the first [[sweep]]'s value, the second's).
  std::vector<std::pair<double, double>> failing;
};

/// One backend's verdict on a claim.
struct ClaimVerdict {
  std::string backend;
  /// "holds", "fails", "holds for dt <= <X> s", "holds for dt >= <X> s", "holds at dt
  /// <list> s only", or "not measured (<why>)"; with "; not measured at dt <list> s" where
  /// some runs have no value to judge (a note instead: a hit the backend resolved by pushing
  /// the bodies apart, say), "; diverged at dt <list> s" where runs blew up and the claim
  /// does not say what that means (they have no numbers to judge), or "; diverged at dt
  /// <list> s, counted as holding" ("as failing") where it does; with "; not judged where
  /// capped at dt <list> s: <reason>" where the engine held a run at a cap of its own (its
  /// numbers are the cap's), or "not measured (capped at ...)".
  std::string verdict;
  VerdictKind kind = VerdictKind::NotMeasured;
  std::vector<double> diverged;  ///< the dts whose runs diverged, largest first
  bool diverged_judged = false;  ///< the claim's `diverged` made them count
  /// A known cause of a verdict other than "holds", computed from the scene and the
  /// backend's settings (claim_causes.hpp); empty when none is known.
  std::string cause;
  std::optional<double> left, right;  ///< the two numbers at report_dt (the reference: its own)
  std::vector<double> capped;         ///< the dts whose runs were capped, largest first
  std::string capped_reason;          ///< the first capped run's reason
  /// The dts whose runs had no value for it, largest first.
  std::vector<double> unmeasured = {};
  /// A map's claim: its counts; then `verdict` is "holds at N of M judged points", "fails at
  /// N of M judged points" or "holds at N of M judged points, fails at F", each with what
  /// was not judged, or "not measured (why)".
  std::optional<RegionCounts> region = {};
};

struct ClaimResult {
  const Claim* claim = nullptr;
  std::vector<ClaimVerdict> verdicts;
};

}  // namespace bb
