// Verdicts on the course text's sentences ([[claim]] in a case file): each claim compared,
// for each backend it names (every one for "*"), at every dt of that backend's sweep. A
// claim that holds at the small steps and fails at the large ones says from which dt it
// holds: a finding, with its numbers.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "run/claim_result.hpp"
#include "run/results.hpp"

namespace bb {

/// Every claim of `results.scene` judged on `results`' runs (a map's claim on its map's
/// points, region_claims.hpp). run_case does this once, after the map, into
/// CaseResults::claims, which every writer reads.
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
  Neither,  ///< no fail, but some backend not measured (at some dt or all, or at some point
            ///< of a map), or with runs diverged unjudged or capped
};
ClaimStanding claim_standing(const ClaimResult& claim);

}  // namespace bb
