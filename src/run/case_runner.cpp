#include "run/case_runner.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>

#include "metrics/order.hpp"
#include "model/text.hpp"
#include "run/accuracy_jobs.hpp"
#include "run/accuracy_run.hpp"
#include "run/child_pool.hpp"
#include "run/claims.hpp"
#include "run/cost_pass.hpp"
#include "run/engine_catalogue.hpp"
#include "run/gates.hpp"
#include "run/interrupt.hpp"
#include "run/run_summary.hpp"
#include "run/stopwatch.hpp"
#include "run/sweep_runner.hpp"
#include "study/backend_names.hpp"
#include "study/case_error.hpp"

namespace bb {

namespace {

/// The case's steps that the options select, largest first.
std::vector<double> selected_dts(const Scene& scene, const RunOptions& options) {
  if (options.dts.empty()) return scene.dt;
  std::vector<double> out;
  for (double asked : options.dts) {
    const auto match = std::find_if(scene.dt.begin(), scene.dt.end(),
                                    [&](double d) { return std::abs(d - asked) <= 1e-9 * d; });
    if (match == scene.dt.end())
      throw CaseError(scene.file, 0,
                      "--dt " + std::to_string(asked) + " is not one of the case's dt");
    if (std::find(out.begin(), out.end(), *match) == out.end()) out.push_back(*match);
  }
  std::sort(out.begin(), out.end(), std::greater<>());
  return out;
}

void check_backend_names(const Scene& scene, const RunOptions& options) {
  const std::vector<std::string> known = backend_names(scene, engine_catalogue());
  for (const std::string& name : options.backends)
    if (!is_import_name(name) && std::find(known.begin(), known.end(), name) == known.end())
      throw CaseError(scene.file, 0,
                      "--backends names '" + name + "', which this case does not run; it runs: " +
                          joined(runnable_backend_names(scene, engine_catalogue())));
}

/// Per backend, its ok run at the smallest dt: the fallback reference of docs/design.md.
std::map<std::string, const RunRecord*> finest_runs(const std::vector<RunRecord>& runs) {
  std::map<std::string, const RunRecord*> out;
  for (const RunRecord& run : runs) {
    if (run.status != RunStatus::Ok || !run.dt) continue;
    const RunRecord*& best = out[run.backend];
    if (best == nullptr || *run.dt < *best->dt) best = &run;
  }
  return out;
}

/// The machine epsilon of a run's arithmetic: float for an engine built in single precision
/// (its settings say so), else double.
double arithmetic_epsilon(const RunRecord& run) {
  for (const auto& [key, value] : run.engine_settings)
    if (key == "precision" && std::holds_alternative<std::string>(value) &&
        std::get<std::string>(value) == "float")
      return std::numeric_limits<float>::epsilon();
  return std::numeric_limits<double>::epsilon();
}

/// The largest body of the scene, as the distance from its centre to its farthest point (m):
/// the motion's scale where the bodies barely move (a ball at rest).
double largest_body_size(const Scene& scene) {
  double size = 0.0;
  for (const Body& b : scene.bodies) size = std::max({size, b.radius, b.half_extents.norm()});
  return size;
}

/// How the reference solved the case, as its run's settings name it.
std::string reference_method(const RunRecord& reference) {
  for (const auto& [key, value] : reference.engine_settings)
    if (key == "method" && std::holds_alternative<std::string>(value))
      return std::get<std::string>(value);
  return "gsl_odeiv2 (" + status_name(reference.status) + " before it started)";
}

}  // namespace

bool backend_wanted(const RunOptions& options, const std::string& name) {
  return options.backends.empty() || std::find(options.backends.begin(), options.backends.end(),
                                               name) != options.backends.end();
}

bool backend_runs(const RunOptions& options, const Scene& scene, const std::string& name) {
  return backend_wanted(options, name) && in_shard(options.shard, scene, name);
}

double time_limit(const Scene& scene, double dt, double timeout) {
  if (timeout > 0.0) return timeout;
  return steps_time_limit(scene, std::ceil(scene.duration / dt));
}

double steps_time_limit(const Scene& scene, double steps) {
  return 10.0 + 2e-5 * steps * static_cast<double>(scene.bodies.size() + scene.springs.size());
}

void check_run_options(const Scene& scene, const RunOptions& options) {
  check_backend_names(scene, options);
  selected_dts(scene, options);
  if (options.sweep) check_map_size(scene, options);
}

int progress_units(const Scene& scene, const Registry& registry, const RunOptions& options) {
  int backends = 0;
  for (const Backend* b : backends_for(scene, registry).all)
    backends += backend_runs(options, scene, b->name());
  const int dts = options.dts.empty() ? static_cast<int>(scene.dt.size())
                                      : static_cast<int>(options.dts.size());
  int sweep = 0;
  if (options.sweep)
    for (const SweepPoint& point : sweep_points(scene))
      sweep += in_shard(options.shard, scene, point_unit(scene, point));
  int imported = 0;
  for (const auto& imported_backend : options.imports)
    imported += static_cast<int>(imported_backend->dts().size());
  const int reference_runs = options.reference_self_check ? 2 : 1;
  return backends * dts + imported + reference_runs + (options.cost ? backends * dts + 1 : 0) +
         sweep;
}

/// The reference's method and self-check (a second solve, `tight`; null when not solved), the
/// floors below which differences from it are noise, and its own observables and series.
void record_reference(const Scene& scene, const ReferenceBackend& reference, const RunRecord* tight,
                      CaseResults& out) {
  out.reference.method = reference_method(out.reference_run);
  out.reference.tolerance = reference.tolerance();
  if (tight) out.reference.self_check_method = reference_method(*tight);
  if (out.reference_run.status != RunStatus::Ok)
    out.reference.self_check_note = "no reference to check";
  else if (!tight)
    out.reference.self_check_note = "not solved (a check of gates needs none)";
  else if (tight->status != RunStatus::Ok)
    out.reference.self_check_note =
        "the second solve is " + status_name(tight->status) + ": " + tight->reason;
  else
    out.reference.self_check =
        max_state_difference(out.reference_run.trajectory, tight->trajectory);
  if (out.reference.self_check) {
    out.reference_floor = compare(scene, out.reference_run.trajectory, tight->trajectory);
    for (const Observe& o : scene.observes) {
      const auto a =
          measure(scene, o, out.reference_run.trajectory, &out.reference_run.trajectory.events)
              .value;
      const auto b = measure(scene, o, tight->trajectory, &tight->trajectory.events).value;
      if (a && b) out.observable_floor[o.name] = std::abs(*a - *b);
    }
  }
  out.versions[reference.library_version().first] = reference.library_version().second;
  add_observables(scene, out.reference_run, out.reference_run);
  add_series(scene, out.reference_run, nullptr);
  record_position_scale(out.reference_run);
}

/// A row for every engine that was not built, so a reader sees why it is absent.
void add_missing_engines(const Scene& scene, const Registry& registry, const RunOptions& options,
                         const std::vector<double>& dts, CaseResults& out) {
  for (const Registry::Missing& missing : registry.missing_engines()) {
    const std::string& name = missing.name;
    const std::string& why = missing.why;
    const bool asked = !options.backends.empty() && backend_wanted(options, name);
    if (!asked && (!missing.shown_unasked || !options.backends.empty())) continue;
    if (!missing.needs.missing_from(scene.features()).empty()) continue;
    for (double dt : dts) {
      RunRecord r;
      r.backend = name;
      r.dt = dt;
      r.status = RunStatus::Unsupported;
      r.reason = why;
      out.runs.push_back(r);
    }
  }
}

/// Errors and observables of every run: against the reference; where it has no answer,
/// against each backend's own run at its finest dt (the fallback of docs/design.md), and
/// reference.method says so.
void measure_runs(const Scene& scene, const std::vector<double>& dts, CaseResults& out) {
  const bool fallback = out.reference_run.status != RunStatus::Ok;
  const std::map<std::string, const RunRecord*> finest = finest_runs(out.runs);
  if (fallback && !finest.empty()) {
    out.reference.method = "none: the reference is " + status_name(out.reference_run.status) +
                           " (" + out.reference_run.reason +
                           "); each backend's errors are against its own run at the finest dt "
                           "of the sweep (self-consistency: convergence, not accuracy)";
    // Where a backend's finest run failed, its errors are against a coarser one: named.
    const double finest_dt = *std::min_element(dts.begin(), dts.end());
    for (const auto& [name, run] : finest)
      if (*run->dt != finest_dt)
        out.reference.method += "; " + name + " against its run at dt " + format_dt(*run->dt) +
                                " (its run at " + format_dt(finest_dt) + " is not ok)";
  }
  for (RunRecord& run : out.runs) {
    if (run.summarised) continue;
    const auto own = finest.find(run.backend);
    const RunRecord* against = !fallback             ? &out.reference_run
                               : own != finest.end() ? own->second
                                                     : nullptr;
    if (ran_to_end(run.status) && against && against != &run && against->status == RunStatus::Ok)
      run.errors = compare(scene, run.trajectory, against->trajectory);
    add_observables(scene, run, against ? *against : out.reference_run);
    if (fallback) add_series(scene, run, nullptr);
    record_position_scale(run);
  }
}

/// Observed order of position_max over the dt sweep, per backend: every run that was
/// started (a failed one has no error), against its floor and its saturation level.
void fit_orders(const Scene& scene, CaseResults& out) {
  const bool fallback = out.reference_run.status != RunStatus::Ok;
  const std::map<std::string, const RunRecord*> finest = finest_runs(out.runs);
  std::map<std::string, std::vector<ErrorPoint>> points;
  const double size = largest_body_size(scene);
  for (const RunRecord& run : out.runs) {
    if (!run.dt || run.status == RunStatus::Unsupported) continue;
    // The floor's and saturation's scales come from whatever the errors are measured against.
    const auto own = finest.find(run.backend);
    const RunRecord* against = fallback && own != finest.end() ? own->second : &out.reference_run;
    if (against == &run) continue;
    out.order_saturation[run.backend] = kSaturationFraction * std::max(against->travel, size);
    // A capped run's error is the cap's, not the step's: no point of the fit.
    const bool fitted = run.errors && run.status != RunStatus::Capped;
    points[run.backend].push_back(
        {*run.dt, fitted ? run.errors->position_max : std::nan(""),
         error_floor(against->position_scale, out.reference.self_check_position(), run.steps,
                     arithmetic_epsilon(run))});
  }
  for (const auto& [name, series] : points) {
    const OrderFit fit = fit_order(series, out.order_saturation[name]);
    if (fit.slope) out.order[name] = *fit.slope;
    out.order_fits[name] = fit;
  }
}

CaseResults run_case(const Scene& scene, const Registry& registry, const RunOptions& options) {
  // Between cases too: kept results take no child process, whose pool would see the signal.
  stop_if_interrupted("the runs of case " + scene.name);
  check_backend_names(scene, options);
  const std::vector<double> dts = selected_dts(scene, options);
  CaseResults out;
  out.scene = &scene;
  out.versions["beachball"] = BEACHBALL_VERSION;
  const auto progress = [&](const std::string& what) {
    if (options.on_progress) options.on_progress(scene.name + ": " + what);
  };

  // Every selected backend at every selected dt.
  const BackendSet set = backends_for(scene, registry);
  std::vector<AccuracyJob> jobs;
  for (const Backend* b : set.all) {
    if (!backend_runs(options, scene, b->name())) continue;
    if (auto v = b->library_version(); !v.first.empty()) out.versions[v.first] = v.second;
    for (double dt : dts) jobs.push_back({b, dt});
  }
  // The programs' trajectories last, each at its own steps: the cost pass times the others.
  const std::size_t timed_jobs = jobs.size();
  for (const auto& imported : options.imports) {
    out.versions[imported->library_version().first] = imported->library_version().second;
    for (double dt : imported->dts()) jobs.push_back({imported.get(), dt});
  }

  // Accuracy runs, each in its own child process: the reference, its self-check (another
  // method, 100 times tighter, smaller steps forced) to measure the reference's own error,
  // then every job, measured in its child (accuracy_jobs.hpp).
  const ReferenceBackend& reference = registry.reference();
  Stopwatch clock;
  AccuracyRuns accuracy = run_accuracy_jobs(scene, reference, jobs, options, progress);
  out.reference_run = std::move(accuracy.reference);
  out.runs = std::move(accuracy.runs);
  const RunRecord& tight = accuracy.tight;
  if (!tight.reused) out.time_spent.self_check_steps = tight.step_seconds;

  record_reference(scene, reference, options.reference_self_check ? &tight : nullptr, out);
  add_missing_engines(scene, registry, options, dts, out);
  measure_runs(scene, dts, out);
  out.time_spent.accuracy = clock.lap();
  for (std::size_t i = timed_jobs; i < jobs.size(); ++i)
    static_cast<const ImportBackend*>(jobs[i].backend)->complete(scene, out.runs[i]);
  time_costs(scene, reference, {jobs.begin(), jobs.begin() + static_cast<long>(timed_jobs)},
             options, progress, out);
  out.time_spent.cost = clock.lap();
  fit_orders(scene, out);

  // The fallback's whole trajectories are done with: keep what the page draws.
  if (out.reference_run.status != RunStatus::Ok)
    for (RunRecord& run : out.runs) keep_plotted_states(scene, run);
  // The reference's states too: from here on every state holds the drawn bodies.
  keep_drawn_states(scene, out.reference_run);

  out.gates = evaluate_gates(scene, out);
  clock.lap();
  if (scene.sweep && options.sweep) out.sweep = run_sweep(scene, registry, options, progress);
  out.time_spent.sweep = clock.lap();
  // After the map: a map's claims are judged on its points.
  out.claims = judge_claims(out);
  return out;
}

CaseResults run_gates(const Scene& scene, const Registry& registry, const RunOptions& base,
                      const RunSelection& also) {
  RunOptions options = base;
  options.backends.clear();
  auto& names = options.backends;
  for (const Gate& g : scene.gates) names.push_back(g.backend);
  names.insert(names.end(), also.backends.begin(), also.backends.end());
  std::sort(names.begin(), names.end());
  names.erase(std::unique(names.begin(), names.end()), names.end());
  options.dts = also.dts;
  if (!scene.gates.empty() || also.dts.empty()) options.dts.push_back(scene.report_dt);
  options.cost = false;
  options.sweep = false;
  // Neither a gate nor a comparison with a baseline uses the reference's own error.
  options.reference_self_check = false;
  if (options.backends.empty()) options.backends.push_back(kReferenceName);
  CaseResults results = run_case(scene, registry, options);
  // Without a reference, errors are against the finest dt: run it too.
  const double finest = *std::min_element(scene.dt.begin(), scene.dt.end());
  const bool has_finest =
      std::find(options.dts.begin(), options.dts.end(), finest) != options.dts.end();
  if (results.reference_run.status != RunStatus::Ok && !has_finest) {
    options.dts.push_back(finest);
    results = run_case(scene, registry, options);
  }
  return results;
}

}  // namespace bb
