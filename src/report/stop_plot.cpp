#include "report/stop_plot.hpp"

#include <algorithm>

#include "observe/event_watches.hpp"
#include "observe/stop_observables.hpp"
#include "report/gnuplot.hpp"
#include "run/drawn_bodies.hpp"
#include "run/run_summary.hpp"

namespace bb {

namespace {

/// The window drawn for `body`: from half a second before the reference's stop (or the
/// start, when it stops early, never stops or has no answer) to the end.
double window_start(const CaseResults& results, int body) {
  const EventTrace& events = results.reference_run.trajectory.events;
  if (static_cast<std::size_t>(body) >= events.bodies.size()) return 0.0;
  const std::optional<double> stop = events.bodies[body].stop_time;
  return stop ? std::max(0.0, *stop - 0.5) : 0.0;
}

}  // namespace

std::vector<int> stopping_bodies(const Scene& scene) {
  std::vector<int> out;
  for (int body : event_watches(scene, scene.observes).stopping)
    if (static_cast<std::size_t>(body) < kPlottedBodies) out.push_back(body);
  std::sort(out.begin(), out.end());
  return out;
}

std::string stop_plot(const CaseResults& results, FileBatch& batch, const std::string& name) {
  const Scene& scene = *results.scene;
  const std::vector<int> bodies = stopping_bodies(scene);
  if (bodies.empty()) return "no body's stop is observed";
  const auto runs = report_runs(results);
  TwoColumnPlot plot(scene.name +
                     ": slid distance and velocity along the slide, around the reference's "
                     "stop, at report_dt");
  const std::vector<int> drawn = drawn_bodies(scene);
  for (int b : bodies) {
    // Where the body sits in the kept states (drawn_bodies.hpp).
    const std::optional<std::size_t> slot = drawn_slot(drawn, b);
    if (!slot) continue;
    const Vec3 along = sliding_direction(scene, b);
    const double from = window_start(results, b);
    for (std::size_t i = 0; i < runs.size(); ++i) {
      const Trajectory& t = runs[i]->trajectory;
      if (t.states.empty()) continue;
      std::vector<double> times, slid, speed;
      for (std::size_t j = 0; j < t.states.size(); ++j) {
        if (t.times[j] < from) continue;
        times.push_back(t.times[j]);
        const BodyState& now = t.states[j][*slot];
        slid.push_back((now.position - t.states.front()[*slot].position).dot(along));
        speed.push_back(now.velocity.dot(along));
      }
      plot.add(false, i, runs[i]->backend, times, slid);
      plot.add(true, i, runs[i]->backend, times, speed);
    }
    const std::string& who = scene.bodies[b].name;
    plot.end_row(who + ": slid (m)", who + ": velocity (m/s)");
  }
  return plot.draw_into(batch, name);
}

}  // namespace bb
