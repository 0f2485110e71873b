#include "run/sweep_runner.hpp"

#include <algorithm>
#include <cmath>

#include "model/text.hpp"
#include "run/child_pool.hpp"
#include "run/map_budget.hpp"
#include "run/stopwatch.hpp"
#include "run/wire.hpp"
#include "study/backend_names.hpp"
#include "study/case_error.hpp"
#include "study/case_limits.hpp"
#include "study/sweep_parameter.hpp"

namespace bb {

namespace {

/// Rows for a point whose child did not come back: one per backend it would have run.
std::vector<RunRecord> lost_point(const Scene& point, const Registry& registry,
                                  const RunOptions& options, const ChildOutcome& outcome) {
  std::vector<std::string> names{kReferenceName};
  for (const Backend* b : backends_for(point, registry).all) names.push_back(b->name());
  std::vector<RunRecord> rows;
  for (const std::string& name : names) {
    if (name != kReferenceName && !backend_wanted(options, name)) continue;
    RunRecord r;
    r.backend = name;
    if (name != kReferenceName) r.dt = point.report_dt;
    r.status =
        outcome.kind == ChildOutcome::Kind::Timeout ? RunStatus::Timeout : RunStatus::Crashed;
    r.reason = "the sweep point's process: " + outcome.reason;
    rows.push_back(r);
  }
  return rows;
}

}  // namespace

std::string sweep_point_unit(double value) {
  return "sweep point " + exact_number(value);
}

std::string point_unit(const Scene& scene, const SweepPoint& point) {
  if (!scene.second_sweep) return sweep_point_unit(point.value);
  return "map point " + exact_number(point.value) + " " + exact_number(point.second_value);
}

namespace {

/// The case with its sweep's parameters set at `point`, run at report_dt (a swept step
/// being that), with no sweep, gates or claims of its own.
Scene point_scene(const Scene& scene, const SweepPoint& at) {
  Scene point = scene;
  set_sweep_parameter(point, scene.sweep->parameter, at.value);
  point.variant = "sweep " + scene.sweep->parameter + " = " + exact_number(at.value);
  if (scene.second_sweep) {
    set_sweep_parameter(point, scene.second_sweep->parameter, at.second_value);
    point.variant += ", " + scene.second_sweep->parameter + " = " + exact_number(at.second_value);
  }
  point.dt = {point.report_dt};
  point.sweep.reset();
  point.second_sweep.reset();
  point.gates.clear();
  point.claims.clear();
  return point;
}

/// What a point is called in progress lines: "k = 100, dt = 0.01".
std::string point_label(const Scene& scene, const SweepPoint& at) {
  std::string label = scene.sweep->parameter + " = " + short_number(at.value);
  if (scene.second_sweep)
    label += ", " + scene.second_sweep->parameter + " = " + short_number(at.second_value);
  return label;
}

/// The point's values exactly, for its kept result's key.
std::string point_values(const Scene& scene, const SweepPoint& at) {
  std::string what = scene.sweep->parameter + " = " + exact_number(at.value);
  if (scene.second_sweep)
    what += "; " + scene.second_sweep->parameter + " = " + exact_number(at.second_value);
  return what;
}

/// A point's runs in its child: the reference's row, then every backend's, encoded.
std::string run_point(const Scene& point, const Registry& registry, const RunOptions& each) {
  CaseResults r = run_case(point, registry, each);
  std::vector<RunRecord> rows{std::move(r.reference_run)};
  for (RunRecord& run : r.runs) rows.push_back(std::move(run));
  // The page draws the point's numbers, not its motion.
  for (RunRecord& row : rows) {
    row.trajectory = Trajectory{};
    row.energy.clear();
    row.distance.clear();
  }
  return wire::encode(rows);
}

/// The points of this machine's share that kept results do not hold, each with its key;
/// those they hold are filled in from them (and said done).
std::vector<std::pair<std::size_t, std::string>> take_kept_points(
    const Scene& scene, const RunOptions& options, SweepResults& out,
    const std::function<void(const std::string&)>& progress) {
  std::vector<std::pair<std::size_t, std::string>> to_run;
  for (std::size_t i = 0; i < out.points.size(); ++i) {
    const SweepPoint at = out.points[i];
    if (!in_shard(options.shard, scene, point_unit(scene, at))) continue;
    // The point's rows depend on the backends asked for, too.
    std::string what = point_values(scene, at) + "; backends:";
    for (const std::string& b : options.backends) what += " " + b;
    const std::string key =
        options.cache ? options.cache->key(scene, "sweep point", what, point_unit(scene, at)) : "";
    if (const auto kept = options.cache ? options.cache->find(key) : std::nullopt) {
      out.points[i].runs = wire::decode_runs(*kept);
      // Kept, not run: its steps took none of this report's time.
      for (RunRecord& run : out.points[i].runs) run.step_seconds = 0.0;
      progress("sweep " + point_label(scene, at));
      continue;
    }
    to_run.emplace_back(i, key);
  }
  return to_run;
}

}  // namespace

Scene sweep_point_scene(const Scene& scene, double value) {
  return point_scene(scene, SweepPoint{value, 0.0, {}});
}

Scene map_point_scene(const Scene& scene, double value, double second) {
  return point_scene(scene, SweepPoint{value, second, {}});
}

std::vector<SweepPoint> sweep_points(const Scene& scene) {
  std::vector<SweepPoint> points;
  if (!scene.sweep) return points;
  for (double value : scene.sweep->values) {
    if (!scene.second_sweep) points.push_back({value, 0.0, {}});
    if (scene.second_sweep)
      for (double second : scene.second_sweep->values) points.push_back({value, second, {}});
  }
  return points;
}

void check_map_size(const Scene& scene, const RunOptions& options) {
  if (!scene.second_sweep) return;
  const MapSize size = map_size(scene, options);
  const double per_point = size.runs_per_point;
  const double runs = size.runs();
  const int shards = options.shard ? options.shard->count : 1;
  if (runs / shards <= kMaxMapRunsPerMachine) return;
  const int needed = static_cast<int>(std::ceil(runs / kMaxMapRunsPerMachine));
  throw CaseError(
      scene.file, scene.second_sweep->line,
      "the map is " + std::to_string(scene.sweep->values.size()) + " x " +
          std::to_string(scene.second_sweep->values.size()) + " points of " +
          short_number(per_point) +
          " runs each (the reference, its self-check and every backend): " + short_number(runs) +
          " runs, more than the " + short_number(kMaxMapRunsPerMachine) + " one machine takes" +
          (shards > 1 ? " in each of " + std::to_string(shards) + " shards" : "") +
          "; shard it over " + std::to_string(needed) +
          " machines or more: `beachball report --shard I/" + std::to_string(needed) +
          "` on each then `beachball merge`, or `scripts/slurm/submit -n " +
          std::to_string(needed) + "`, or take fewer points or backends");
}

SweepResults run_sweep(const Scene& scene, const Registry& registry, const RunOptions& options,
                       const std::function<void(const std::string&)>& progress) {
  SweepResults out{scene.sweep->parameter, sweep_points(scene),
                   scene.second_sweep ? scene.second_sweep->parameter : ""};
  RunOptions each = options;
  each.dts.clear();
  each.jobs = 1;
  each.cost = false;
  each.sweep = false;
  each.on_progress = nullptr;
  each.on_note = nullptr;
  // A point is one unit of a shard: all of it runs where it runs.
  each.shard.reset();
  // A point is kept whole (in this process), not run by run in its child.
  each.cache = nullptr;
  // A point runs the reference, its self-check and every backend, each with its own limit.
  const std::size_t runs = backends_for(scene, registry).all.size() + 2;
  ChildPool pool(options.jobs, options.isolation);
  std::vector<std::pair<std::size_t, std::string>> to_run =
      take_kept_points(scene, options, out, progress);
  const auto submit = [&](std::size_t i, const std::string& key,
                          const std::function<void()>& then) {
    const std::string label = point_label(scene, out.points[i]);
    // A swept step sets the point's own limit.
    const Scene point = point_scene(scene, out.points[i]);
    const double limit =
        static_cast<double>(runs) * time_limit(point, point.report_dt, options.timeout);
    pool.submit(
        label, [&registry, &each, point] { return run_point(point, registry, each); }, limit,
        [&, i, point, label, key, then](const ChildOutcome& outcome) {
          out.points[i].runs = outcome.kind == ChildOutcome::Kind::Done
                                   ? wire::decode_runs(outcome.payload)
                                   : lost_point(point, registry, options, outcome);
          const std::vector<RunRecord>& rows = out.points[i].runs;
          if (!key.empty())
            options.cache->keep(
                key,
                outcome.kind == ChildOutcome::Kind::Done ? outcome.payload : wire::encode(rows),
                outcome.kind == ChildOutcome::Kind::Done &&
                    std::all_of(rows.begin(), rows.end(), RunCache::repeatable));
          progress("sweep " + label);
          if (then) then();
        });
  };
  // A map's point with the most steps runs first, alone: the others' time is estimated from
  // it and said before they start (map_budget.hpp). A one-parameter sweep runs all at once.
  Stopwatch alone;
  if (scene.second_sweep && !to_run.empty()) {
    const auto first =
        std::max_element(to_run.begin(), to_run.end(), [&](const auto& a, const auto& b) {
          return point_steps(scene, out.points[a.first]) < point_steps(scene, out.points[b.first]);
        });
    const std::pair<std::size_t, std::string> head = *first;
    to_run.erase(first);
    // It runs alone: its wall time is the pool's until it is done.
    submit(head.first, head.second, [&, head] {
      const double seconds = alone.lap();
      std::vector<const SweepPoint*> rest;
      for (const auto& [i, key] : to_run) rest.push_back(&out.points[i]);
      if (options.on_note && !rest.empty())
        options.on_note(map_estimate_text(
            scene, estimate_map(scene, out.points[head.first], seconds, rest, options.jobs)));
      for (const auto& [i, key] : to_run) submit(i, key, nullptr);
    });
  } else {
    for (const auto& [i, key] : to_run) submit(i, key, nullptr);
  }
  pool.run();
  return out;
}

}  // namespace bb
