#include "run/region_claims.hpp"

#include <map>

#include "model/text.hpp"
#include "run/map_theory.hpp"
#include "study/case_error.hpp"

namespace bb {

namespace {

/// Whether `outcome` is the one `word` ("ok", "exploded") names.
bool is_claimed_outcome(const std::string& word, MapOutcome outcome) {
  if (word == "ok") return outcome == MapOutcome::Ok;
  return outcome == MapOutcome::PastOnset || outcome == MapOutcome::Diverged;
}

const RunRecord* region_row(const SweepPoint& point, const std::string& backend) {
  for (const RunRecord& run : point.runs)
    if (run.backend == backend) return &run;
  return nullptr;
}

}  // namespace

std::vector<RegionPoint> region_points(const CaseResults& results, const Claim& claim) {
  std::vector<RegionPoint> out;
  if (!results.sweep || !claim.region) return out;
  const Scene& scene = *results.scene;
  const RegionClaim& g = *claim.region;
  // The map's theory for the backend (the one its picture draws) and the axis it bounds; its
  // bound at each value of the other axis (the point's own value of the bounded one does not
  // move it).
  const MapTheory* theory = map_theory(scene, g.backend);
  const bool bounded_first = theory != nullptr && bounds_first_sweep(scene, *theory);
  std::map<double, double> bound_at;
  for (const BoundaryPoint& b : map_boundary(scene, g.backend)) bound_at[b.value] = b.limit;
  for (const SweepPoint& p : results.sweep->points) {
    const double bounded = bounded_first ? p.value : p.second_value;
    const double other = bounded_first ? p.second_value : p.value;
    RegionPoint r;
    r.outcome = map_outcome(scene, region_row(p, g.backend));
    if (const auto limit = bound_at.find(other); limit != bound_at.end()) {
      r.boundary = limit->second * g.boundary_factor;
      r.place = bounded < *r.boundary * (1.0 - g.margin)   ? RegionPlace::Inside
                : bounded > *r.boundary * (1.0 + g.margin) ? RegionPlace::Outside
                                                           : RegionPlace::WithinMargin;
    }
    const std::string* word = r.place == RegionPlace::Inside    ? &g.inside
                              : r.place == RegionPlace::Outside ? &g.outside
                                                                : nullptr;
    r.judged = word != nullptr && *word != "any" && ran_to_an_outcome(r.outcome);
    r.held = r.judged && is_claimed_outcome(*word, r.outcome);
    out.push_back(r);
  }
  return out;
}

ClaimVerdict judge_region_claim(const CaseResults& results, const Claim& claim) {
  const RegionClaim& g = *claim.region;
  ClaimVerdict v;
  v.backend = g.backend;
  if (!results.sweep) {
    v.verdict = "not measured (the map did not run)";
    return v;
  }
  const std::vector<RegionPoint> points = region_points(results, claim);
  RegionCounts n;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const RegionPoint& r = points[i];
    const SweepPoint& p = results.sweep->points[i];
    if (r.place == RegionPlace::NoTheory) {
      ++n.no_theory;
    } else if (r.place == RegionPlace::WithinMargin) {
      ++n.within_margin;
    } else if ((r.place == RegionPlace::Inside ? g.inside : g.outside) == "any") {
      ++n.unclaimed;
    } else if (!r.judged) {
      ++n.no_outcome;
    } else {
      ++n.judged;
      n.held += r.held;
      if (!r.held) n.failing.emplace_back(p.value, p.second_value);
    }
  }
  const int failed = n.judged - n.held;
  const std::string of = std::to_string(n.judged) + " judged point" + (n.judged == 1 ? "" : "s");
  if (n.judged == 0) {
    v.kind = VerdictKind::NotMeasured;
    v.verdict = "not measured (no point judged";
  } else if (failed == 0) {
    v.kind = VerdictKind::Holds;
    v.verdict = "holds at " + std::to_string(n.held) + " of " + of;
  } else if (n.held == 0) {
    v.kind = VerdictKind::Fails;
    v.verdict = "fails at " + std::to_string(failed) + " of " + of;
  } else {
    v.kind = VerdictKind::Partial;
    v.verdict =
        "holds at " + std::to_string(n.held) + " of " + of + ", fails at " + std::to_string(failed);
  }
  // Every point of the map is accounted for: what was not judged, and why.
  const std::vector<std::pair<int, std::string>> apart = {
      {n.within_margin, "within " + short_number(100.0 * g.margin) + " % of the boundary"},
      {n.unclaimed, "on a side the claim does not state"},
      {n.no_outcome, "without an outcome (unsupported, failed or not run)"},
      {n.no_theory, "where the theory gives no bound"}};
  std::string rest;
  for (const auto& [count, why] : apart)
    if (count > 0) rest += (rest.empty() ? "" : ", ") + std::to_string(count) + " " + why;
  if (n.judged == 0) {
    v.verdict += rest.empty() ? ")" : ": " + rest + ")";
  } else if (!rest.empty()) {
    v.verdict += "; not judged: " + rest;
  }
  v.region = n;
  return v;
}

void require_region_theory(const Scene& scene) {
  for (const Claim& claim : scene.claims) {
    if (!claim.region || map_theory(scene, claim.region->backend)) continue;
    throw CaseError(scene.file, claim.line,
                    "[[claim]] with region = \"theory\" names backend '" + claim.region->backend +
                        "', for which no theory bounds '" + scene.sweep->parameter + "' or '" +
                        scene.second_sweep->parameter +
                        "' at every point of this map; the theories bound " + map_theories_cover());
  }
}

}  // namespace bb
