#include "run/claims.hpp"

#include <algorithm>
#include <cmath>

#include "model/text.hpp"
#include "run/claim_causes.hpp"
#include "run/region_claims.hpp"
#include "study/backend_names.hpp"
#include "study/metric_names.hpp"

namespace bb {

namespace {

/// Backend `backend`'s runs: the reference's one, or one per dt, largest dt first.
std::vector<const RunRecord*> runs_of(const CaseResults& results, const std::string& backend) {
  if (backend == kReferenceName) return {&results.reference_run};
  std::vector<const RunRecord*> out;
  for (const RunRecord& run : results.runs)
    if (run.backend == backend) out.push_back(&run);
  return out;
}

/// The run of `backend` at `dt` (the reference's whatever the dt), or null.
const RunRecord* run_at(const CaseResults& results, const std::string& backend,
                        std::optional<double> dt) {
  for (const RunRecord* run : runs_of(results, backend))
    if (backend == kReferenceName || run->dt == dt) return run;
  return nullptr;
}

/// The value of one side of a claim, for the backend being judged at `dt`: the quantity,
/// or with compare = "error" its distance from the reference's.
std::optional<double> side_value(const CaseResults& results, const Claim& claim,
                                 const ClaimSide& side, const std::string& judged,
                                 std::optional<double> dt) {
  if (side.is_number()) return side.number;
  const std::string backend = side.backend == "*" ? judged : side.backend;
  const RunRecord* run = run_at(results, backend, dt);
  // A named engine or course variant without this dt is read at report_dt.
  if (run == nullptr) run = run_at(results, backend, results.scene->report_dt);
  if (run == nullptr) return std::nullopt;
  if (!claim.against_reference) return run_quantity(*run, side.metric);
  return run->status == RunStatus::Ok ? metric_value(*run, side.metric) : std::nullopt;
}

std::string listed(const std::vector<double>& dts) {
  std::string list;
  for (double dt : dts) list += (list.empty() ? "" : ", ") + format_dt(dt);
  return list;
}

/// "holds", "fails", or the steps it holds at, from the dts where it held and failed.
std::pair<std::string, VerdictKind> core_verdict(const std::vector<double>& holding,
                                                 const std::vector<double>& failing) {
  if (failing.empty()) return {"holds", VerdictKind::Holds};
  if (holding.empty()) return {"fails", VerdictKind::Fails};
  const auto [hold_min, hold_max] = std::minmax_element(holding.begin(), holding.end());
  const auto [fail_min, fail_max] = std::minmax_element(failing.begin(), failing.end());
  if (*hold_max < *fail_min)
    return {"holds for dt <= " + format_dt(*hold_max) + " s", VerdictKind::Partial};
  // A claim that something goes wrong at a game's step holds at the large steps.
  if (*hold_min > *fail_max)
    return {"holds for dt >= " + format_dt(*hold_min) + " s", VerdictKind::Partial};
  return {"holds at dt " + listed(holding) + " s only", VerdictKind::Partial};
}

ClaimVerdict judge(const CaseResults& results, const Claim& claim, const std::string& backend) {
  ClaimVerdict v;
  v.backend = backend;
  std::vector<double> holding, failing;  // the dts, largest first
  const RunRecord* at_report = nullptr;
  for (const RunRecord* run : runs_of(results, backend)) {
    const bool report_row = !run->dt || *run->dt == results.scene->report_dt;
    if (report_row) at_report = run;
    if (run->status == RunStatus::Diverged) {
      // A run that blew up has no numbers; the claim says whether that is evidence.
      v.diverged.push_back(run->dt.value_or(0.0));
      if (claim.diverged == DivergedCounts::Holds) holding.push_back(run->dt.value_or(0.0));
      if (claim.diverged == DivergedCounts::Fails) failing.push_back(run->dt.value_or(0.0));
      continue;
    }
    if (run->status == RunStatus::Capped) {
      // A run its engine held at a cap has the cap's numbers, not the scene's: not judged.
      v.capped.push_back(run->dt.value_or(0.0));
      if (v.capped.size() == 1) v.capped_reason = run->reason;
      continue;
    }
    const std::optional<double> l = side_value(results, claim, claim.left, backend, run->dt);
    const std::optional<double> r = side_value(results, claim, claim.right, backend, run->dt);
    if (report_row) v.left = l, v.right = r;
    if (!l || !r) {
      v.unmeasured.push_back(run->dt.value_or(0.0));
      continue;
    }
    (claim_holds(claim.op, *l, *r, claim.tolerance) ? holding : failing)
        .push_back(run->dt.value_or(0.0));
  }
  v.diverged_judged = claim.diverged != DivergedCounts::Nothing && !v.diverged.empty();
  const std::string blew_up =
      v.diverged.empty() ? "" : "diverged at dt " + listed(v.diverged) + " s";
  const std::string capped =
      v.capped.empty() ? "" : "capped at dt " + listed(v.capped) + " s: " + v.capped_reason;
  if (holding.empty() && failing.empty()) {
    v.kind = VerdictKind::NotMeasured;
    // A backend that cannot run the case says why (the features it lacks).
    const bool unsupported = at_report != nullptr && at_report->status == RunStatus::Unsupported;
    const std::string why = !blew_up.empty() && !capped.empty() ? blew_up + "; " + capped
                            : !blew_up.empty()                  ? blew_up
                            : !capped.empty()                   ? capped
                            : unsupported ? "unsupported: " + at_report->reason
                                          : backend + " has no value for it";
    v.verdict = "not measured (" + why + ")";
  } else {
    std::tie(v.verdict, v.kind) = core_verdict(holding, failing);
    // The steps it could not judge are named: a verdict from some dts is not one from all.
    if (!v.unmeasured.empty()) v.verdict += "; not measured at dt " + listed(v.unmeasured) + " s";
    if (!blew_up.empty())
      v.verdict += "; " + blew_up +
                   (claim.diverged == DivergedCounts::Holds   ? ", counted as holding"
                    : claim.diverged == DivergedCounts::Fails ? ", counted as failing"
                                                              : "");
    if (!capped.empty()) v.verdict += "; not judged where " + capped;
  }
  if (v.kind != VerdictKind::Holds && at_report != nullptr)
    v.cause = known_cause(*results.scene, *at_report);
  return v;
}

bool is_error_metric(const std::string& name) {
  const auto& names = error_metric_names();
  return std::find(names.begin(), names.end(), name) != names.end();
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
    if (claim.region) {
      r.verdicts.push_back(judge_region_claim(results, claim));
      out.push_back(std::move(r));
      continue;
    }
    std::vector<std::string> backends;
    if (claim.left.backend == "*") {
      if (!results.reference_run.backend.empty() && judges_the_reference(claim))
        backends.push_back(kReferenceName);
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

bool judges_the_reference(const Claim& claim) {
  if (claim.left.backend != "*") return claim.left.backend == kReferenceName;
  // Errors are measured against the reference, and a comparison with the reference is no
  // comparison for the reference itself: it has nothing of its own to judge.
  return !claim.against_reference && !is_error_metric(claim.left.metric) &&
         claim.right.backend != kReferenceName;
}

ClaimStanding claim_standing(const ClaimResult& claim) {
  bool neither = false;
  for (const ClaimVerdict& v : claim.verdicts) {
    if (v.kind == VerdictKind::Fails || v.kind == VerdictKind::Partial) return ClaimStanding::Fails;
    neither = neither || v.kind == VerdictKind::NotMeasured || !v.unmeasured.empty() ||
              (!v.diverged.empty() && !v.diverged_judged) || !v.capped.empty() ||
              (v.region && v.region->no_outcome > 0);
  }
  return neither ? ClaimStanding::Neither : ClaimStanding::Holds;
}

}  // namespace bb
