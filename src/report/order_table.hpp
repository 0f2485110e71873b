// The order of convergence per backend, with the local slopes it comes from, or why there
// is none.
#pragma once

#include <string>

#include "report/table.hpp"
#include "run/results.hpp"

namespace bb {

/// "1.19 [1.32 1.48] 1.68": each local slope, smallest dt first, the fitted ones in brackets.
std::string local_slopes_text(const OrderFit& fit);
/// One row per backend: order (or "none"), local slopes, points in the fit, and the reason.
Table order_table(const CaseResults& results);
/// The page's paragraph on the order column, and the table.
std::string order_markdown(const CaseResults& results);

}  // namespace bb
