#include "run/map_budget.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "model/text.hpp"
#include "run/engine_catalogue.hpp"
#include "run/shard.hpp"
#include "run/sweep_runner.hpp"
#include "study/backend_names.hpp"

namespace bb {

MapSize map_size(const Scene& scene, const RunOptions& options) {
  MapSize size;
  if (!scene.second_sweep) return size;
  size.rows = scene.sweep->values.size();
  size.columns = scene.second_sweep->values.size();
  // The reference and its self-check, then each backend asked for that can run the case.
  size.runs_per_point = 2;
  for (const std::string& name : runnable_backend_names(scene, engine_catalogue()))
    if (name != kReferenceName && backend_wanted(options, name)) ++size.runs_per_point;
  for (const SweepPoint& point : sweep_points(scene))
    size.points_here += in_shard(options.shard, scene, point_unit(scene, point));
  return size;
}

std::string map_size_text(const Scene& scene, const RunOptions& options) {
  if (!scene.second_sweep || !options.sweep) return "";
  const MapSize size = map_size(scene, options);
  return fmt::format(
      "{}: a map of {} x {} points of {} runs each (the reference, its self-check and each "
      "backend run): {} runs{}; its time is estimated from its first point to run, once that "
      "has run",
      scene.name, size.rows, size.columns, size.runs_per_point, short_number(size.runs_here()),
      options.shard ? fmt::format(" in this shard ({} of its {} points)", size.points_here,
                                  size.rows * size.columns)
                    : "");
}

double point_steps(const Scene& scene, const SweepPoint& point) {
  const Scene at = map_point_scene(scene, point.value, point.second_value);
  return scene.duration / at.report_dt;
}

MapEstimate estimate_map(const Scene& scene, const SweepPoint& first, double first_seconds,
                         const std::vector<const SweepPoint*>& rest, int jobs) {
  MapEstimate e;
  e.first_seconds = first_seconds;
  for (const RunRecord& run : first.runs) e.first_step_seconds += run.step_seconds;
  e.first_step_seconds = std::min(e.first_step_seconds, first_seconds);
  e.rest_points = rest.size();
  e.jobs = std::max(jobs, 1);
  const double outside_steps = first_seconds - e.first_step_seconds;
  const double first_steps = point_steps(scene, first);
  double total = 0.0;
  for (const SweepPoint* p : rest)
    total += outside_steps + e.first_step_seconds * point_steps(scene, *p) / first_steps;
  // The points share the jobs (no more of them busy than there are points).
  e.rest_seconds = total / std::min<double>(e.jobs, std::max<std::size_t>(rest.size(), 1));
  return e;
}

std::string map_estimate_text(const Scene& scene, const MapEstimate& e) {
  return fmt::format(
      "{}: the map's first point took {:.2f} s ({:.2f} s of it in its runs' steps); the other "
      "{} points to run: about {} s on {} jobs (estimated from that point: its time "
      "outside its steps once per point, its steps' time in proportion to each point's steps)",
      scene.name, e.first_seconds, e.first_step_seconds, e.rest_points,
      e.rest_seconds < 10.0 ? fmt::format("{:.1f}", e.rest_seconds)
                            : fmt::format("{:.0f}", e.rest_seconds),
      e.jobs);
}

}  // namespace bb
