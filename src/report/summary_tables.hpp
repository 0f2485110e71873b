// The tables a reader looks at first, shared by the terminal and the Markdown page.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "report/table.hpp"
#include "run/results.hpp"

namespace bb {

/// One row per backend at `dt` (the reference first): errors, observables, cost, order.
Table summary_table(const CaseResults& results, double dt);
/// Rows a backend gets in the per-body table at most: its worst bodies.
inline constexpr std::size_t kPerBodyRows = 10;
/// Each backend's errors at `dt` body by body, worst first (the kPerBodyRows worst of a larger
/// scene: `cut` says so), against what the summary table's errors are against.
struct PerBodyErrors {
  Table table;
  bool cut = false;
};
PerBodyErrors per_body_errors(const CaseResults& results, double dt);
/// Why runs at `dt` that are not ok ended as they did, one line each.
std::vector<std::string> run_notes(const CaseResults& results, double dt);
/// Every run of the sweep, one row per (backend, dt).
Table sweep_table(const CaseResults& results);
/// "not monotone: stable up to 0.0201 s; unstable from 0.0202 to 0.0249 s (why); stable
/// again from 0.025 to 0.0325 s; unstable again from 0.0326 s (why)".
std::string stability_bands_text(const StabilityResult& result);
/// One row per backend of the stability search, with theory beside it.
Table stability_table(const CaseResults& results);
/// One row per gate: backend, metric, value, limit, pass or fail.
Table gate_table(const CaseResults& results);

}  // namespace bb
