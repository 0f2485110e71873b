#include "report/stop_plot.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "metrics/stop_observables.hpp"
#include "report/gnuplot.hpp"
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
  for (const Observe& o : scene.observes) {
    const bool stop = o.kind == "stop_time" || o.kind == "stop_distance" || o.kind == "rest_creep";
    if (stop && static_cast<std::size_t>(o.body) < kPlottedBodies &&
        std::find(out.begin(), out.end(), o.body) == out.end())
      out.push_back(o.body);
  }
  std::sort(out.begin(), out.end());
  return out;
}

std::string stop_plot(const CaseResults& results, FileBatch& batch, const std::string& name) {
  const Scene& scene = *results.scene;
  const std::vector<int> bodies = stopping_bodies(scene);
  if (bodies.empty()) return "no body's stop is observed";
  const auto runs = report_runs(results);
  std::string data,
      script = fmt::format(
          "set multiplot layout {},2 title {}\nset grid\n"
          "set key at screen 0.99, screen 0.94 right top maxrows 20 samplen 2 font \",9\"\n",
          bodies.size(),
          quote(scene.name + ": slid distance and velocity along the slide, around the "
                             "reference's stop, at report_dt"));
  int block = 0;
  for (int b : bodies) {
    const Vec3 along = sliding_direction(scene, b);
    const double from = window_start(results, b);
    std::string distance_plot, velocity_plot;
    for (std::size_t i = 0; i < runs.size(); ++i) {
      const Trajectory& t = runs[i]->trajectory;
      if (t.states.empty()) continue;
      std::vector<double> times, slid, speed;
      for (std::size_t j = 0; j < t.states.size(); ++j) {
        if (t.times[j] < from) continue;
        times.push_back(t.times[j]);
        slid.push_back((t.states[j][b].position - t.states.front()[b].position).dot(along));
        speed.push_back(t.states[j][b].velocity.dot(along));
      }
      if (times.empty()) continue;
      data += "# " + runs[i]->backend + " distance\n" + series_rows(times, slid) + "\n\n";
      distance_plot += (distance_plot.empty() ? "plot " : ", \\\n     ") +
                       series_line(i, block++, runs[i]->backend);
      data += "# " + runs[i]->backend + " velocity\n" + series_rows(times, speed) + "\n\n";
      velocity_plot += (velocity_plot.empty() ? "plot " : ", \\\n     ") +
                       series_line(i, block++, runs[i]->backend);
    }
    if (distance_plot.empty()) continue;
    const std::string& who = scene.bodies[b].name;
    // Two columns side by side, the legend (drawn with the first panel only) right of both.
    script += fmt::format(
        "set lmargin at screen 0.07\nset rmargin at screen 0.39\nset xlabel \"t (s)\"\n"
        "set ylabel {}\n{}\nunset key\n",
        quote(who + ": slid (m)"), distance_plot);
    script +=
        fmt::format("set lmargin at screen 0.47\nset rmargin at screen 0.79\nset ylabel {}\n{}\n",
                    quote(who + ": velocity (m/s)"), velocity_plot);
  }
  if (block == 0) return "no run at report_dt has states to draw";
  return draw(script + "unset multiplot\n", data, batch, name,
              80 + 260 * static_cast<int>(bodies.size()));
}

}  // namespace bb
