#include "run/claims.hpp"

#include <algorithm>
#include <cmath>

#include "scene/text.hpp"

namespace bb {

namespace {

/// Backend `backend`'s runs: the reference's one, or one per dt, largest dt first.
std::vector<const RunRecord*> runs_of(const CaseResults& results, const std::string& backend) {
  if (backend == "reference") return {&results.reference_run};
  std::vector<const RunRecord*> out;
  for (const RunRecord& run : results.runs)
    if (run.backend == backend) out.push_back(&run);
  return out;
}

/// The run of `backend` at `dt` (the reference's whatever the dt), or null.
const RunRecord* run_at(const CaseResults& results, const std::string& backend,
                        std::optional<double> dt) {
  for (const RunRecord* run : runs_of(results, backend))
    if (backend == "reference" || run->dt == dt) return run;
  return nullptr;
}

/// The value of one side of a claim, for the backend being judged at `dt`.
std::optional<double> side_value(const CaseResults& results, const ClaimSide& side,
                                 const std::string& judged, std::optional<double> dt) {
  if (side.is_number()) return side.number;
  const std::string backend = side.backend == "*" ? judged : side.backend;
  const RunRecord* run = run_at(results, backend, dt);
  // A named engine or course variant without this dt is read at report_dt.
  if (run == nullptr) run = run_at(results, backend, results.scene->report_dt);
  return run ? run_quantity(*run, side.metric) : std::nullopt;
}

ClaimVerdict judge(const CaseResults& results, const Claim& claim, const std::string& backend) {
  ClaimVerdict v{backend, "", std::nullopt, std::nullopt};
  std::vector<double> holding, failing, diverged;  // the dts, largest first
  bool any = false;
  for (const RunRecord* run : runs_of(results, backend)) {
    // A run that blew up has no numbers: the verdict says where, rather than skip it.
    if (run->status == RunStatus::Diverged) diverged.push_back(run->dt.value_or(0.0));
    const std::optional<double> l = side_value(results, claim.left, backend, run->dt);
    const std::optional<double> r = side_value(results, claim.right, backend, run->dt);
    const bool at_report = !run->dt || *run->dt == results.scene->report_dt;
    if (at_report) v.left = l, v.right = r;
    if (!l || !r) continue;
    any = true;
    (claim_holds(claim.op, *l, *r, claim.tolerance) ? holding : failing)
        .push_back(run->dt.value_or(0.0));
  }
  const auto listed = [](const std::vector<double>& dts) {
    std::string list;
    for (double dt : dts) list += (list.empty() ? "" : ", ") + format_dt(dt);
    return list;
  };
  const std::string blew_up = diverged.empty() ? "" : "diverged at dt " + listed(diverged) + " s";
  if (!any) {
    v.verdict =
        "not measured (" + (blew_up.empty() ? backend + " has no value for it" : blew_up) + ")";
    return v;
  }
  if (failing.empty()) {
    v.verdict = "holds";
  } else if (holding.empty()) {
    v.verdict = "fails";
  } else if (*std::max_element(holding.begin(), holding.end()) <
             *std::min_element(failing.begin(), failing.end())) {
    v.verdict =
        "holds for dt <= " + format_dt(*std::max_element(holding.begin(), holding.end())) + " s";
  } else {
    v.verdict = "holds at dt " + listed(holding) + " s only";
  }
  if (!blew_up.empty()) v.verdict += "; " + blew_up;
  return v;
}

}  // namespace

bool claim_holds(const std::string& op, double left, double right, double tolerance) {
  if (op == "<") return left < right;
  if (op == "<=") return left <= right;
  if (op == ">") return left > right;
  if (op == ">=") return left >= right;
  return std::abs(left - right) <= tolerance;
}

std::vector<ClaimResult> judge_claims(const CaseResults& results) {
  std::vector<ClaimResult> out;
  for (const Claim& claim : results.scene->claims) {
    ClaimResult r{&claim, {}};
    std::vector<std::string> backends;
    if (claim.left.backend == "*") {
      if (!results.reference_run.backend.empty()) backends.push_back("reference");
      for (const RunRecord& run : results.runs)
        if (std::find(backends.begin(), backends.end(), run.backend) == backends.end())
          backends.push_back(run.backend);
    } else {
      backends.push_back(claim.left.backend);
    }
    for (const std::string& b : backends) r.verdicts.push_back(judge(results, claim, b));
    out.push_back(std::move(r));
  }
  return out;
}

}  // namespace bb
