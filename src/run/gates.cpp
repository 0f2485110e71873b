#include "run/gates.hpp"

#include <algorithm>
#include <cmath>

namespace bb {

namespace {

const RunRecord* find_run(const CaseResults& results, const std::string& backend, double dt) {
  for (const RunRecord& r : results.runs)
    if (r.backend == backend && r.dt && *r.dt == dt) return &r;
  return nullptr;
}

}  // namespace

std::vector<GateResult> evaluate_gates(const Scene& scene, const CaseResults& results) {
  std::vector<GateResult> out;
  // Without the reference, every error and observable difference is against the backend's
  // own finest run (the fallback): each gate says so.
  const std::string against =
      results.reference_run.status == RunStatus::Ok
          ? std::string()
          : "against its own run at the finest dt, not the reference (which has no answer: " +
                results.reference_run.reason + ")";
  for (const Gate& gate : scene.gates) {
    GateResult g{gate, std::nullopt, false, "", against};
    const RunRecord* run = find_run(results, gate.backend, scene.report_dt);
    if (run == nullptr) {
      g.note = "no run of " + gate.backend + " at report_dt";
    } else if (run->status != RunStatus::Ok) {
      g.note = gate.backend + " " + status_name(run->status) + ": " + run->reason;
    } else {
      g.value = metric_value(*run, gate.metric);
      g.passed = g.value && *g.value <= gate.max;
      if (!g.value) g.note = "the run has no value for " + gate.metric;
    }
    out.push_back(g);
  }
  return out;
}

}  // namespace bb
