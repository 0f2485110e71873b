#include "run/sweep_runner.hpp"

#include <algorithm>

#include "run/child_pool.hpp"
#include "run/wire.hpp"
#include "scene/sweep_parameter.hpp"
#include "scene/text.hpp"

namespace bb {

namespace {

/// Rows for a point whose child did not come back: one per backend it would have run.
std::vector<RunRecord> lost_point(const Scene& point, const Registry& registry,
                                  const RunOptions& options, const ChildOutcome& outcome) {
  std::vector<std::string> names{"reference"};
  for (const Backend* b : backends_for(point, registry).all) names.push_back(b->name());
  std::vector<RunRecord> rows;
  for (const std::string& name : names) {
    if (name != "reference" && !backend_wanted(options, name)) continue;
    RunRecord r;
    r.backend = name;
    if (name != "reference") r.dt = point.report_dt;
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

Scene sweep_point_scene(const Scene& scene, double value) {
  Scene point = scene;
  set_sweep_parameter(point, scene.sweep->parameter, value);
  point.dt = {scene.report_dt};
  point.sweep.reset();
  point.gates.clear();
  point.claims.clear();
  point.variant = "sweep " + scene.sweep->parameter + " = " + exact_number(value);
  return point;
}

SweepResults run_sweep(const Scene& scene, const Registry& registry, const RunOptions& options,
                       const std::function<void(const std::string&)>& progress) {
  const Sweep& sweep = *scene.sweep;
  SweepResults out{sweep.parameter, {}};
  out.points.resize(sweep.values.size());
  RunOptions each = options;
  each.dts.clear();
  each.jobs = 1;
  each.cost = false;
  each.sweep = false;
  each.on_progress = nullptr;
  // A point is one unit of a shard: all of it runs where it runs.
  each.shard.reset();
  // A point is kept whole (in this process), not run by run in its child.
  each.cache = nullptr;
  // A point runs the reference, its self-check and every backend, each with its own limit.
  const std::size_t runs = backends_for(scene, registry).all.size() + 2;
  const double limit =
      static_cast<double>(runs) * time_limit(scene, scene.report_dt, options.timeout);
  ChildPool pool(options.jobs, options.isolation);
  for (std::size_t i = 0; i < sweep.values.size(); ++i) {
    const double value = sweep.values[i];
    out.points[i].value = value;
    if (!in_shard(options.shard, scene, sweep_point_unit(value))) continue;
    const std::string label = sweep.parameter + " = " + short_number(value);
    // The point's rows depend on the backends asked for, too.
    std::string what = sweep.parameter + " = " + exact_number(value) + "; backends:";
    for (const std::string& b : options.backends) what += " " + b;
    const std::string key =
        options.cache ? options.cache->key(scene, "sweep point", what, sweep_point_unit(value))
                      : "";
    if (const auto kept = options.cache ? options.cache->find(key) : std::nullopt) {
      out.points[i].runs = wire::decode_runs(*kept);
      // Kept, not run: its steps took none of this report's time.
      for (RunRecord& run : out.points[i].runs) run.step_seconds = 0.0;
      progress("sweep " + label);
      continue;
    }
    pool.submit(
        label,
        [&scene, &registry, &each, value] {
          const Scene point = sweep_point_scene(scene, value);
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
        },
        limit,
        [&, i, value, label, key](const ChildOutcome& outcome) {
          out.points[i].runs =
              outcome.kind == ChildOutcome::Kind::Done
                  ? wire::decode_runs(outcome.payload)
                  : lost_point(sweep_point_scene(scene, value), registry, options, outcome);
          const std::vector<RunRecord>& rows = out.points[i].runs;
          if (!key.empty())
            options.cache->keep(
                key,
                outcome.kind == ChildOutcome::Kind::Done ? outcome.payload : wire::encode(rows),
                outcome.kind == ChildOutcome::Kind::Done &&
                    std::all_of(rows.begin(), rows.end(), RunCache::repeatable));
          progress("sweep " + label);
        });
  }
  pool.run();
  return out;
}

}  // namespace bb
