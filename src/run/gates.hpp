// Checking a case's [[gate]]s against its runs at report_dt.
#pragma once

#include "run/results.hpp"

namespace bb {

/// One result per gate. An error metric is compared as is; an observable by the size of
/// its difference from the reference. A gate whose run is missing or not ok fails.
std::vector<GateResult> evaluate_gates(const Scene& scene, const CaseResults& results);

}  // namespace bb
