#include "run/case_runner.hpp"

#include <algorithm>
#include <cmath>
#include <ctime>
#include <functional>
#include <limits>

#include "metrics/order.hpp"
#include "run/accuracy_jobs.hpp"
#include "run/accuracy_run.hpp"
#include "run/child_pool.hpp"
#include "run/claims.hpp"
#include "run/engine_catalogue.hpp"
#include "run/gates.hpp"
#include "run/run_summary.hpp"
#include "run/stopwatch.hpp"
#include "run/sweep_runner.hpp"
#include "run/wire.hpp"
#include "scene/backend_names.hpp"
#include "scene/case_error.hpp"
#include "scene/text.hpp"

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
    if (std::find(known.begin(), known.end(), name) == known.end())
      throw CaseError(scene.file, 0,
                      "--backends names '" + name + "', which this case does not run; it runs: " +
                          joined(runnable_backend_names(scene, engine_catalogue())));
}

/// Per backend, its ok run at the smallest dt: the fallback reference of DESIGN.md.
std::map<std::string, const RunRecord*> finest_runs(const std::vector<RunRecord>& runs) {
  std::map<std::string, const RunRecord*> out;
  for (const RunRecord& run : runs) {
    if (run.status != RunStatus::Ok || !run.dt) continue;
    const RunRecord*& best = out[run.backend];
    if (best == nullptr || *run.dt < *best->dt) best = &run;
  }
  return out;
}

/// A cost measurement: a run's step and how many calls of step() it takes.
struct Measure {
  double dt = 0.0;
  long calls = 0;
};

/// Fills each run's cost from its timing; `measured_at` says when a kept one was timed.
void apply_timings(const std::vector<RunRecord*>& runs, const std::vector<Measure>& measures,
                   const std::vector<Timing>& timings, const std::string& measured_at) {
  for (std::size_t k = 0; k < runs.size() && k < timings.size(); ++k) {
    RunRecord& run = *runs[k];
    const Timing& t = timings[k];
    Cost c;
    c.repeats = t.repeats;
    const auto per_step = [&](double seconds) {
      return run.steps > 0 ? seconds * 1e9 / static_cast<double>(run.steps) : 0.0;
    };
    c.ns_per_step = per_step(t.median_seconds);
    c.ns_per_step_min = per_step(t.min_seconds);
    c.ns_per_step_max = per_step(t.max_seconds);
    c.seconds_per_simulated_second =
        t.median_seconds / (static_cast<double>(measures[k].calls) * measures[k].dt);
    c.measured_at = measured_at;
    run.cost = c;
  }
}

/// What decides a batch's timings beyond the backend and the case: each run's step and
/// calls, and how the pass times them.
std::string cost_role(const std::vector<Measure>& measures, const CostOptions& cost) {
  std::string role = "cost";
  for (const Measure& m : measures)
    role += " " + exact_number(m.dt) + "x" + std::to_string(m.calls);
  return role + " " + exact_number(cost.min_seconds) + " " + std::to_string(cost.min_repeats) +
         " " + exact_number(cost.enough_seconds) + " " + exact_number(cost.max_seconds_per_repeat) +
         " " + std::to_string(cost.max_repeats);
}

/// The time now, UTC, to the second (ISO 8601).
std::string utc_now() {
  const std::time_t now = std::time(nullptr);
  std::tm utc{};
  gmtime_r(&now, &utc);
  char text[32];
  std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%SZ", &utc);
  return text;
}

/// Queues the cost measurement of `runs`, all of `backend`, in one child of the serial pool
/// (a fork per backend rather than per run), filling each run's cost when it is done. A
/// measurement that crashes or times out leaves the batch's runs without a cost. A batch
/// kept from an earlier invocation is not timed again: its costs say when they were.
void queue_costs(ChildPool& pool, const Backend& backend, const Scene& scene,
                 std::vector<RunRecord*> runs, const RunOptions& options,
                 const std::function<void(const std::string&)>& progress) {
  std::erase_if(runs, [](const RunRecord* r) {
    return r->status != RunStatus::Ok && r->status != RunStatus::Diverged;
  });
  if (runs.empty()) return;
  // The reference is stepped sample by sample; its cost per step is per internal step.
  std::vector<Measure> measures;
  const CostOptions cost = options.cost_options;
  double limit = 0.0;
  for (const RunRecord* run : runs) {
    const Measure m{run->dt ? *run->dt : scene.sample, run->dt ? run->steps : scene.sample_count()};
    measures.push_back(m);
    limit += 4.0 * time_limit(scene, m.dt, options.timeout) + 10.0 * cost.min_seconds;
  }
  const std::string key =
      options.cache ? options.cache->key(scene, cost_role(measures, cost), backend, std::nullopt)
                    : "";
  if (const auto kept = options.cache ? options.cache->find(key) : std::nullopt) {
    const std::size_t line = kept->find('\n');
    apply_timings(runs, measures, wire::decode_timings(kept->substr(line + 1)),
                  kept->substr(0, line));
    for (RunRecord* run : runs) progress("cost of " + run->backend);
    return;
  }
  pool.submit(
      "cost of " + backend.name(),
      [&backend, &scene, measures, cost] {
        std::vector<Timing> timings;
        for (const Measure& m : measures)
          timings.push_back(time_steps(backend, scene, m.dt, m.calls, cost));
        return wire::encode(timings);
      },
      limit,
      [runs, measures, progress, key, &options](const ChildOutcome& outcome) {
        for (RunRecord* run : runs) progress("cost of " + run->backend);
        if (outcome.kind != ChildOutcome::Kind::Done) return;
        apply_timings(runs, measures, wire::decode_timings(outcome.payload), "");
        if (!key.empty()) options.cache->keep(key, utc_now() + "\n" + outcome.payload);
      });
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
  const double steps = std::ceil(scene.duration / dt);
  return 10.0 + 2e-5 * steps * static_cast<double>(scene.bodies.size() + scene.springs.size());
}

void check_run_options(const Scene& scene, const RunOptions& options) {
  check_backend_names(scene, options);
  selected_dts(scene, options);
}

int progress_units(const Scene& scene, const Registry& registry, const RunOptions& options) {
  int backends = 0;
  for (const Backend* b : backends_for(scene, registry).all)
    backends += backend_runs(options, scene, b->name());
  const int dts = options.dts.empty() ? static_cast<int>(scene.dt.size())
                                      : static_cast<int>(options.dts.size());
  int sweep = 0;
  if (scene.sweep && options.sweep)
    for (double value : scene.sweep->values)
      sweep += in_shard(options.shard, scene, sweep_point_unit(value));
  return backends * dts + 2 + (options.cost ? backends * dts + 1 : 0) + sweep;
}

/// The reference's method and self-check (a second solve, `tight`), the floors below
/// which differences from it are noise, and its own observables and series.
void record_reference(const Scene& scene, const ReferenceBackend& reference, const RunRecord& tight,
                      CaseResults& out) {
  out.reference.method = reference_method(out.reference_run);
  out.reference.tolerance = reference.tolerance();
  out.reference.self_check_method = reference_method(tight);
  if (out.reference_run.status != RunStatus::Ok)
    out.reference.self_check_note = "no reference to check";
  else if (tight.status != RunStatus::Ok)
    out.reference.self_check_note =
        "the second solve is " + status_name(tight.status) + ": " + tight.reason;
  else
    out.reference.self_check = max_state_difference(out.reference_run.trajectory, tight.trajectory);
  if (out.reference_run.status == RunStatus::Ok && tight.status == RunStatus::Ok) {
    out.reference_floor = compare(scene, out.reference_run.trajectory, tight.trajectory);
    for (const Observe& o : scene.observes) {
      const auto a =
          measure(scene, o, out.reference_run.trajectory, &out.reference_run.trajectory.events)
              .value;
      const auto b = measure(scene, o, tight.trajectory, &tight.trajectory.events).value;
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
/// against each backend's own run at its finest dt (DESIGN.md's fallback), and
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
    if (run.status == RunStatus::Ok && against && against != &run &&
        against->status == RunStatus::Ok)
      run.errors = compare(scene, run.trajectory, against->trajectory);
    add_observables(scene, run, against ? *against : out.reference_run);
    if (fallback) add_series(scene, run, nullptr);
    record_position_scale(run);
  }
}

/// The cost pass, when asked for: serial, after every accuracy run, so runs do not disturb
/// its timing.
void time_costs(const Scene& scene, const ReferenceBackend& reference,
                const std::vector<AccuracyJob>& jobs, const RunOptions& options,
                const std::function<void(const std::string&)>& progress, CaseResults& out) {
  if (options.cost) {
    ChildPool serial(1, options.isolation);
    queue_costs(serial, reference, scene, {&out.reference_run}, options, progress);
    // One child per backend measures all its runs, in the order of the sweep.
    for (std::size_t i = 0; i < jobs.size(); ++i) {
      if (i > 0 && jobs[i].backend == jobs[i - 1].backend) continue;
      std::vector<RunRecord*> runs;
      for (std::size_t k = i; k < jobs.size() && jobs[k].backend == jobs[i].backend; ++k)
        runs.push_back(&out.runs[k]);
      queue_costs(serial, *jobs[i].backend, scene, runs, options, progress);
    }
    serial.run();
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
    points[run.backend].push_back(
        {*run.dt, run.errors ? run.errors->position_max : std::nan(""),
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

  // Accuracy runs, each in its own child process: the reference, its self-check (another
  // method, 100 times tighter, smaller steps forced) to measure the reference's own error,
  // then every job, measured in its child (accuracy_jobs.hpp).
  const ReferenceBackend& reference = registry.reference();
  Stopwatch clock;
  AccuracyRuns accuracy = run_accuracy_jobs(scene, reference, jobs, options, progress);
  out.reference_run = std::move(accuracy.reference);
  out.runs = std::move(accuracy.runs);
  const RunRecord& tight = accuracy.tight;

  record_reference(scene, reference, tight, out);
  add_missing_engines(scene, registry, options, dts, out);
  measure_runs(scene, dts, out);
  out.time_spent.accuracy = clock.lap();
  time_costs(scene, reference, jobs, options, progress, out);
  out.time_spent.cost = clock.lap();
  fit_orders(scene, out);

  // The fallback's whole trajectories are done with: keep what the page draws.
  if (out.reference_run.status != RunStatus::Ok)
    for (RunRecord& run : out.runs) keep_plotted_states(scene, run);
  // The reference's states too: from here on every state holds the drawn bodies.
  keep_drawn_states(scene, out.reference_run);

  out.gates = evaluate_gates(scene, out);
  out.claims = judge_claims(out);
  clock.lap();
  if (scene.sweep && options.sweep) out.sweep = run_sweep(scene, registry, options, progress);
  out.time_spent.sweep = clock.lap();
  return out;
}

CaseResults run_gates(const Scene& scene, const Registry& registry, const RunOptions& base) {
  RunOptions options = base;
  options.backends.clear();
  for (const Gate& g : scene.gates) {
    auto& names = options.backends;
    if (std::find(names.begin(), names.end(), g.backend) == names.end()) names.push_back(g.backend);
  }
  options.dts = {scene.report_dt};
  options.cost = false;
  options.sweep = false;
  if (options.backends.empty()) options.backends.push_back("reference");
  CaseResults results = run_case(scene, registry, options);
  // Without a reference, errors are against the finest dt: run it too.
  const double finest = *std::min_element(scene.dt.begin(), scene.dt.end());
  if (results.reference_run.status != RunStatus::Ok && finest != scene.report_dt) {
    options.dts = {scene.report_dt, finest};
    results = run_case(scene, registry, options);
  }
  return results;
}

}  // namespace bb
