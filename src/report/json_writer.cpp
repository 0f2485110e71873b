#include "report/json_writer.hpp"

#include "run/claims.hpp"
#include "run/cost.hpp"

namespace bb {

namespace {

using Json = nlohmann::ordered_json;

template <typename T>
Json optional_json(const std::optional<T>& v) {
  return v ? Json(*v) : Json(nullptr);
}

Json settings_json(const Settings& settings) {
  Json out = Json::object();
  for (const auto& [key, value] : settings)
    std::visit([&, &k = key](const auto& v) { out[k] = v; }, value);
  return out;
}

/// A run's errors: the worst body's figures, which body that is, and every body's.
Json errors_json(const ErrorMetrics& e, const Scene& scene) {
  Json j = {{"position_max", e.position_max},
            {"position_rms", e.position_rms},
            {"position_final", e.position_final},
            {"velocity_max", e.velocity_max},
            {"energy_max", e.energy_max}};
  if (e.bodies.empty() || e.bodies.size() != scene.bodies.size()) return j;
  j["worst_body"] = scene.bodies[static_cast<std::size_t>(e.worst_body())].name;
  j["bodies"] = Json::object();
  for (std::size_t i = 0; i < e.bodies.size(); ++i)
    j["bodies"][scene.bodies[i].name] = {{"position_max", e.bodies[i].position_max},
                                         {"position_rms", e.bodies[i].position_rms},
                                         {"position_final", e.bodies[i].position_final},
                                         {"velocity_max", e.bodies[i].velocity_max}};
  return j;
}

Json run_json(const RunRecord& run, const Scene& scene) {
  Json j;
  j["backend"] = run.backend;
  j["dt"] = optional_json(run.dt);
  j["status"] = status_name(run.status);
  j["reason"] = run.reason;
  j["diverged_at"] = optional_json(run.diverged_at);
  j["steps"] = run.steps;
  if (run.cost) {
    j["cost"] = {{"ns_per_step", run.cost->ns_per_step},
                 {"seconds_per_simulated_second", run.cost->seconds_per_simulated_second},
                 {"repeats", run.cost->repeats},
                 {"ns_per_step_min", run.cost->ns_per_step_min},
                 {"ns_per_step_median", run.cost->ns_per_step},
                 {"ns_per_step_max", run.cost->ns_per_step_max},
                 {"busy", timed_on_a_busy_machine(*run.cost)}};
    // A cost kept from an earlier invocation says when it was timed.
    if (!run.cost->measured_at.empty()) j["cost"]["measured_at"] = run.cost->measured_at;
  } else {
    j["cost"] = nullptr;
  }
  if (run.errors)
    j["errors"] = errors_json(*run.errors, scene);
  else
    j["errors"] = nullptr;
  j["observables"] = Json::object();
  for (const ObservableResult& o : run.observables) {
    Json v;
    v["value"] = optional_json(o.measured.value);
    v["reference"] = optional_json(o.reference);
    v["error"] =
        o.measured.value && o.reference ? Json(*o.measured.value - *o.reference) : Json(nullptr);
    if (!o.measured.note.empty()) v["note"] = o.measured.note;
    j["observables"][o.name] = v;
  }
  j["engine_settings"] = settings_json(run.engine_settings);
  if (!run.messages.empty()) j["messages"] = run.messages;
  return j;
}

/// How the reference was solved, and its self-check: the largest difference of each state
/// component from a second solve by another method (self_check: positions, m, as always;
/// the others added beside it), null when there was none, with the reason.
Json reference_json(const ReferenceInfo& ref) {
  const auto check = [&](double StateDifference::*part) {
    return ref.self_check ? Json((*ref.self_check).*part) : Json(nullptr);
  };
  return {{"method", ref.method},
          {"tolerance", ref.tolerance},
          {"self_check", check(&StateDifference::position)},
          {"self_check_velocity", check(&StateDifference::velocity)},
          {"self_check_orientation", check(&StateDifference::orientation)},
          {"self_check_spin", check(&StateDifference::spin)},
          {"self_check_method", ref.self_check_method},
          {"self_check_note", ref.self_check_note}};
}

/// The orders of convergence: each backend's slope, how many points its fit used and how
/// many sat at or below their error floor, and the fit in full (its order or why there is
/// none, and the local slopes).
void add_orders(const CaseResults& results, Json& j) {
  j["order"] = Json::object();
  for (const auto& [name, slope] : results.order) j["order"][name] = slope;
  j["order_fit"] = Json::object();
  for (const auto& [name, fit] : results.order_fits)
    j["order_fit"][name] = {{"points", fit.used}, {"below_floor", fit.below_floor}};
  j["order_detail"] = Json::object();
  for (const auto& [name, fit] : results.order_fits) {
    Json slopes = Json::array();
    for (const LocalSlope& s : fit.local_slopes)
      slopes.push_back(
          {{"dt", {s.dt_small, s.dt_large}}, {"slope", s.slope}, {"in_fit", s.in_fit}});
    const auto saturation = results.order_saturation.find(name);
    j["order_detail"][name] = {
        {"order", optional_json(fit.slope)},
        {"reason", fit.reason},
        {"points", fit.used},
        {"below_floor", fit.below_floor},
        {"saturated", fit.saturated},
        {"failed", fit.failed},
        {"saturation",
         saturation == results.order_saturation.end() ? Json(nullptr) : Json(saturation->second)},
        {"local_slopes", slopes}};
  }
}

/// A map's claim counted over its points, with the points where it failed.
Json region_counts_json(const RegionCounts& n) {
  Json failing = Json::array();
  for (const auto& [value, second] : n.failing)
    failing.push_back({{"value", value}, {"second_value", second}});
  return {{"judged", n.judged},
          {"held", n.held},
          {"within_margin", n.within_margin},
          {"unclaimed", n.unclaimed},
          {"no_outcome", n.no_outcome},
          {"no_theory", n.no_theory},
          {"failing", failing}};
}

/// Each claim's verdict per backend, computed from the runs.
Json claims_json(const CaseResults& results) {
  Json out = Json::array();
  for (const ClaimResult& c : results.claims) {
    Json verdicts = Json::object();
    for (const ClaimVerdict& v : c.verdicts) {
      verdicts[v.backend] = {{"verdict", v.verdict},
                             {"left", optional_json(v.left)},
                             {"right", optional_json(v.right)},
                             {"cause", v.cause}};
      if (v.region) verdicts[v.backend]["points"] = region_counts_json(*v.region);
    }
    out.push_back({{"text", c.claim->text},
                   {"seed", c.claim->seed},
                   {"quote", c.claim->quote},
                   {"own", c.claim->own},
                   {"verdicts", verdicts}});
  }
  return out;
}

/// Each backend's stability search, with each stretch of steps with one verdict, smallest
/// first: more than two where stability is not monotone in dt.
Json stability_json(const CaseResults& results) {
  Json out = Json::object();
  for (const StabilityResult& r : results.stability) {
    Json bands = Json::array();
    for (const StabilityBand& b : r.bands)
      bands.push_back({{"from", b.from}, {"to", b.to}, {"stable", b.stable}, {"reason", b.reason}});
    out[r.backend] = {{"critical_dt", optional_json(r.critical_dt)},
                      {"unstable_dt", optional_json(r.unstable_dt)},
                      {"status", r.status},
                      {"reason", r.reason},
                      {"stable_note", r.stable_note},
                      {"bands", bands},
                      {"theory", optional_json(r.theory)},
                      {"theory_formula", r.theory_formula},
                      {"theory_note", r.theory_note},
                      {"trials", r.trials}};
  }
  return out;
}

/// The case at each value of its [[sweep]], every backend at report_dt; null without one.
/// A map's gives both parameters, each one's values once, and each point's two values.
Json sweep_json(const CaseResults& results) {
  if (!results.sweep) return nullptr;
  const SweepResults& swept = *results.sweep;
  const bool map = !swept.second_parameter.empty();
  Json sweep = {{"parameter", swept.parameter}, {"values", Json::array()}};
  if (map) {
    sweep["values"] = results.scene->sweep->values;
    sweep["second_parameter"] = swept.second_parameter;
    sweep["second_values"] = results.scene->second_sweep->values;
  }
  sweep["points"] = Json::array();
  for (const SweepPoint& p : swept.points) {
    if (!map) sweep["values"].push_back(p.value);
    Json rows = Json::array();
    for (const RunRecord& run : p.runs) rows.push_back(run_json(run, *results.scene));
    Json point = {{"value", p.value}};
    if (map) point["second_value"] = p.second_value;
    point["runs"] = rows;
    sweep["points"].push_back(point);
  }
  return sweep;
}

/// Each gate with its value and whether it passed.
Json gates_json(const CaseResults& results) {
  Json out = Json::array();
  for (const GateResult& g : results.gates)
    out.push_back({{"backend", g.gate.backend},
                   {"metric", g.gate.metric},
                   {"max", g.gate.max},
                   {"value", optional_json(g.value)},
                   {"passed", g.passed},
                   {"note", g.note}});
  return out;
}

}  // namespace

Json results_json(const CaseResults& results) {
  const Scene& scene = *results.scene;
  Json j;
  j["schema"] = "beachball-results/1";
  j["case"] = scene.name;
  j["title"] = scene.title;
  j["seed"] = scene.seed;
  j["sample"] = scene.sample;
  j["report_dt"] = scene.report_dt;
  j["versions"] = results.versions;
  // A stability search alone has no reference and no runs.
  const bool has_runs = !results.reference_run.backend.empty();
  j["reference"] = has_runs ? reference_json(results.reference) : Json(nullptr);
  j["runs"] = Json::array();
  if (has_runs) j["runs"].push_back(run_json(results.reference_run, *results.scene));
  for (const RunRecord& run : results.runs) j["runs"].push_back(run_json(run, *results.scene));
  add_orders(results, j);
  j["claims"] = claims_json(results);
  j["stability"] = stability_json(results);
  j["sweep"] = sweep_json(results);
  j["gates"] = gates_json(results);
  return j;
}

}  // namespace bb
