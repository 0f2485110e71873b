// The claims ledger (reports/claims.md): every [[claim]] of the suite, one row each, with
// its verdict per backend and the two numbers behind it, computed from the runs.
#pragma once

#include <string>
#include <vector>

#include "run/results.hpp"

namespace bb {

/// The ledger's Markdown for the cases in `all`.
std::string claims_page(const std::vector<CaseResults>& all);

}  // namespace bb
