#include "run/gates.hpp"

#include <algorithm>
#include <cmath>

#include "scene/metric_names.hpp"

namespace bb {

namespace {

const RunRecord* find_run(const CaseResults& results, const std::string& backend, double dt) {
  for (const RunRecord& r : results.runs)
    if (r.backend == backend && r.dt && *r.dt == dt) return &r;
  return nullptr;
}

std::optional<double> gate_value(const RunRecord& run, const std::string& metric) {
  const auto& names = error_metric_names();
  if (std::find(names.begin(), names.end(), metric) != names.end())
    return run.errors ? std::optional<double>(run.errors->get(metric)) : std::nullopt;
  for (const ObservableResult& o : run.observables)
    if (o.name == metric && o.measured.value && o.reference)
      return std::abs(*o.measured.value - *o.reference);
  return std::nullopt;
}

}  // namespace

std::vector<GateResult> evaluate_gates(const Scene& scene, const CaseResults& results) {
  std::vector<GateResult> out;
  for (const Gate& gate : scene.gates) {
    GateResult g{gate, std::nullopt, false, ""};
    const RunRecord* run = find_run(results, gate.backend, scene.report_dt);
    if (run == nullptr) {
      g.note = "no run of " + gate.backend + " at report_dt";
    } else if (run->status != RunStatus::Ok) {
      g.note = gate.backend + " " + status_name(run->status) + ": " + run->reason;
    } else {
      g.value = gate_value(*run, gate.metric);
      g.passed = g.value && *g.value <= gate.max;
      if (!g.value) g.note = "the run has no value for " + gate.metric;
    }
    out.push_back(g);
  }
  return out;
}

}  // namespace bb
