#include "report/summary_tables.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "report/cost_noise.hpp"
#include "report/format.hpp"

namespace bb {

namespace {

std::optional<double> error_of(const RunRecord& run, const char* name) {
  return run.errors ? std::optional<double>(run.errors->get(name)) : std::nullopt;
}

std::string status_cell(const RunRecord& run) {
  if (run.status == RunStatus::Diverged && run.diverged_at)
    return fmt::format("diverged at {:.3g} s", *run.diverged_at);
  return status_name(run.status);
}

std::string observable_cell(const ObservableResult& o, bool is_reference) {
  if (!o.measured.value) return "-";
  // The reference row compares with itself, except where a formula gives the value to reach.
  if (!o.reference || (is_reference && *o.reference == *o.measured.value))
    return format_value(o.measured.value);
  // On the reference row a bracket is never "from the reference": it says what it is from.
  return format_value(o.measured.value) + " (" + format_value(*o.measured.value - *o.reference) +
         (is_reference ? " from the formula)" : ")");
}

/// The cell of a named observable, "-" where the run has none (it failed before measuring).
std::string observable_cell(const RunRecord& run, const std::string& name, bool is_reference) {
  for (const ObservableResult& o : run.observables)
    if (o.name == name) return observable_cell(o, is_reference);
  return "-";
}

/// The body whose position_max the row shows, "-" where there are no per-body errors.
std::string worst_body_cell(const RunRecord& run, const Scene& scene) {
  if (!run.errors || run.errors->bodies.empty() || run.errors->bodies.size() != scene.bodies.size())
    return "-";
  return scene.bodies[static_cast<std::size_t>(run.errors->worst_body())].name;
}

}  // namespace

Table summary_table(const CaseResults& results, double dt) {
  const Scene& scene = *results.scene;
  // With more than one body the errors are the worst body's: the table names it.
  const bool named = scene.bodies.size() > 1;
  Table t;
  t.headers = {"backend",     "status",      "pos max m", "pos rms m",
               "pos final m", "vel max m/s", "energy max"};
  if (named) t.headers.insert(t.headers.begin() + 3, "worst body");
  for (const Observe& o : scene.observes) t.headers.push_back(o.name);
  for (const char* h : {"ns/step", "s per sim s", "order"}) t.headers.push_back(h);
  t.right_aligned.assign(t.headers.size(), true);
  t.right_aligned[0] = t.right_aligned[1] = false;
  if (named) t.right_aligned[3] = false;
  const auto add = [&](const RunRecord& run, bool is_reference) {
    std::vector<std::string> row = {run.backend, status_cell(run)};
    for (const char* m :
         {"position_max", "position_rms", "position_final", "velocity_max", "energy_max"})
      row.push_back(is_reference ? "-" : format_value(error_of(run, m)));
    if (named) row.insert(row.begin() + 3, is_reference ? "-" : worst_body_cell(run, scene));
    for (const Observe& o : scene.observes)
      row.push_back(observable_cell(run, o.name, is_reference));
    row.push_back(cost_ns_cell(run.cost));
    row.push_back(cost_seconds_cell(run.cost));
    const auto order = results.order.find(run.backend);
    row.push_back(order == results.order.end() ? "-" : fmt::format("{:.2f}", order->second));
    t.rows.push_back(row);
  };
  add(results.reference_run, true);
  for (const RunRecord& run : results.runs)
    if (run.dt && *run.dt == dt) add(run, false);
  return t;
}

std::vector<std::string> run_notes(const CaseResults& results, double dt) {
  std::vector<std::string> notes;
  // Without a reference no error can be measured: the first note says why there is none.
  const RunRecord& reference = results.reference_run;
  if (reference.status != RunStatus::Ok) {
    const bool fallback = std::any_of(results.runs.begin(), results.runs.end(),
                                      [](const RunRecord& r) { return r.errors.has_value(); });
    notes.push_back("reference: " + status_name(reference.status) + ": " + reference.reason +
                    (fallback ? "; errors are against each backend's own run at its finest dt"
                              : "; without it no error column can be filled"));
  }
  for (const RunRecord& run : results.runs) {
    if (!run.dt || *run.dt != dt) continue;
    if (run.status != RunStatus::Ok) {
      notes.push_back(run.backend + ": " + status_name(run.status) + ": " + run.reason);
      continue;
    }
    // An observable the reference has and this run lacks (a bounce it never made).
    for (const ObservableResult& o : run.observables)
      if (!o.measured.value && o.reference && !o.measured.note.empty())
        notes.push_back(run.backend + ": " + o.name + ": " + o.measured.note);
  }
  return notes;
}

Table sweep_table(const CaseResults& results) {
  Table t;
  t.headers = {"backend", "dt s", "status", "steps", "pos max m", "vel max m/s", "energy max"};
  // Each observable at every dt: a claim that holds at one step and fails at another shows here.
  for (const Observe& o : results.scene->observes) t.headers.push_back(o.name);
  for (const char* h : {"ns/step", "ns/step fastest-slowest", "s per sim s"})
    t.headers.push_back(h);
  t.right_aligned.assign(t.headers.size(), true);
  t.right_aligned[0] = t.right_aligned[2] = false;
  for (const RunRecord& run : results.runs) {
    if (run.status == RunStatus::Unsupported) continue;
    std::vector<std::string> row = {run.backend,
                                    format_dt(*run.dt),
                                    status_cell(run),
                                    std::to_string(run.steps),
                                    format_value(error_of(run, "position_max")),
                                    format_value(error_of(run, "velocity_max")),
                                    format_value(error_of(run, "energy_max"))};
    for (const Observe& o : results.scene->observes)
      row.push_back(observable_cell(run, o.name, false));
    row.push_back(cost_ns_cell(run.cost));
    row.push_back(cost_spread_cell(run.cost));
    row.push_back(cost_seconds_cell(run.cost));
    t.rows.push_back(row);
  }
  return t;
}

std::string stability_bands_text(const StabilityResult& r) {
  std::string out = "not monotone:";
  for (std::size_t i = 0; i < r.bands.size(); ++i) {
    const StabilityBand& b = r.bands[i];
    const std::string verdict =
        std::string(b.stable ? "stable" : "unstable") + (i >= 2 ? " again" : "");
    const std::string range =
        i == 0 ? (b.from == b.to ? "at " : "up to ") + format_value(b.to) + " s"
        : i + 1 == r.bands.size()
            ? "from " + format_value(b.from) + " s"
            : "from " + format_value(b.from) + " to " + format_value(b.to) + " s";
    out += (i > 0 ? "; " : " ") + verdict + " " + range;
    if (!b.stable && !b.reason.empty()) out += " (" + b.reason + ")";
  }
  return out;
}

Table stability_table(const CaseResults& results) {
  Table t;
  t.headers = {"backend", "largest stable dt s", "smallest unstable dt s", "theory s", "result"};
  t.right_aligned = {false, true, true, true, false};
  for (const StabilityResult& r : results.stability) {
    std::string result = r.status == "not monotone" ? stability_bands_text(r) : r.status;
    if (r.status != "not monotone" && !r.reason.empty()) result += ": " + r.reason;
    if (!r.stable_note.empty()) result += "; at the largest stable step the " + r.stable_note;
    t.rows.push_back({r.backend, format_value(r.critical_dt), format_value(r.unstable_dt),
                      !r.theory          ? "-"
                      : *r.theory == 0.0 ? r.theory_formula
                                         : format_value(r.theory) + " (" + r.theory_formula + ")",
                      result});
  }
  return t;
}

Table gate_table(const CaseResults& results) {
  Table t;
  t.headers = {"backend", "metric", "value", "max", "result"};
  t.right_aligned = {false, false, true, true, false};
  for (const GateResult& g : results.gates)
    t.rows.push_back({g.gate.backend, g.gate.metric, format_value(g.value),
                      format_value(g.gate.max),
                      (g.passed ? "pass" : "FAIL" + (g.note.empty() ? "" : ": " + g.note)) +
                          (g.against.empty() ? "" : " (" + g.against + ")")});
  return t;
}

PerBodyErrors per_body_errors(const CaseResults& results, double dt) {
  const Scene& scene = *results.scene;
  PerBodyErrors out;
  out.table.headers = {"backend", "body", "pos max m", "pos rms m", "pos final m", "vel max m/s"};
  out.table.right_aligned = {false, false, true, true, true, true};
  for (const RunRecord& run : results.runs) {
    if (!run.dt || *run.dt != dt || !run.errors) continue;
    const std::vector<BodyErrors>& bodies = run.errors->bodies;
    if (bodies.size() != scene.bodies.size()) continue;
    // The bodies worst first; a large scene keeps each backend's kPerBodyRows worst.
    std::vector<std::size_t> order(bodies.size());
    for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
      return bodies[a].position_max > bodies[b].position_max;
    });
    if (order.size() > kPerBodyRows) {
      order.resize(kPerBodyRows);
      out.cut = true;
    }
    for (std::size_t i : order)
      out.table.rows.push_back(
          {run.backend, scene.bodies[i].name, format_value(bodies[i].position_max),
           format_value(bodies[i].position_rms), format_value(bodies[i].position_final),
           format_value(bodies[i].velocity_max)});
  }
  return out;
}

}  // namespace bb
