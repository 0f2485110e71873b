// The claims ledger (reports/claims.md): every [[claim]] of the suite, one row each, with
// the course text's words it tests, its verdict per backend and the two numbers behind it,
// computed from the runs. A case's page shows the same rows for its own claims.
#pragma once

#include <string>
#include <vector>

#include "report/table.hpp"
#include "run/results.hpp"

namespace bb {

/// The ledger's Markdown for the cases in `all`.
std::string claims_page(const std::vector<CaseResults>& all);

/// The claims of one case: the sentence, the course text's words (or that it is the case's
/// own), and every backend's verdict with its numbers; no rows when the case has none.
Table case_claims_table(const CaseResults& results);

}  // namespace bb
