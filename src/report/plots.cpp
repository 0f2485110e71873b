#include "report/plots.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <optional>
#include <utility>

#include "report/backend_style.hpp"
#include "report/bodies_plot.hpp"
#include "report/body_panels.hpp"
#include "report/energy_plot.hpp"
#include "report/gnuplot.hpp"
#include "report/map_claim_picture.hpp"
#include "report/map_difference.hpp"
#include "report/map_difference_picture.hpp"
#include "report/map_picture.hpp"
#include "report/motion_view.hpp"
#include "report/plot_layout.hpp"
#include "report/rotation_plot.hpp"
#include "report/stop_plot.hpp"
#include "report/sweep_page.hpp"
#include "report/work_precision.hpp"
#include "run/drawn_bodies.hpp"
#include "run/engine_catalogue.hpp"
#include "run/run_summary.hpp"
#include "study/backend_names.hpp"

namespace bb {

namespace {

std::string metric_label(const std::string& metric) {
  if (metric.starts_with("position")) return metric + " (m)";
  if (metric == "velocity_max") return metric + " (m/s)";
  if (metric == "energy_max") return metric + " (relative)";
  return "|" + metric + " - reference|";
}

std::string work_precision_plot(const CaseResults& results, const std::string& metric,
                                FileBatch& batch, const std::string& name) {
  const std::vector<WorkSeries> series = work_series(results, metric);
  const bool timed =
      !series.empty() && !series.front().points.empty() && series.front().points.front().cost;
  std::string data, plot;
  int block = 0;
  for (std::size_t i = 0; i < series.size(); ++i) {
    std::string rows;
    for (const WorkPoint& p : series[i].points)
      if (p.error > 0.0 && std::isfinite(p.error))
        rows += fmt::format("{:.17g} {:.17g}\n", timed ? *p.cost : p.dt, p.error);
    if (rows.empty()) continue;
    data += "# " + series[i].backend + "\n" + rows + "\n\n";
    const BackendStyle style = backend_style(series[i].backend);
    plot += fmt::format(
        "{}data index {} using 1:2 with linespoints lw 2 dt {} pt {} ps 1.2 lc rgb \"{}\" title {}",
        plot.empty() ? "plot " : ", \\\n     ", block++, style.kind == LineKind::Engine ? 2 : 1,
        1 + i % 13, style.colour, quote(series[i].backend));
  }
  if (plot.empty()) return "no run has a value for " + metric;
  if (const auto floor = metric_floor(results, metric); floor && *floor > 0.0)
    plot += fmt::format(
        ", \\\n     {:.17g} with lines dt 2 lw 2 lc rgb \"black\" title \"reference self-check "
        "(error floor)\"",
        *floor);
  const std::string script = fmt::format(
      "set logscale xy\nset format x \"%.0e\"\nset format y \"%.0e\"\nset grid\nset key outside "
      "right top\n"
      "set xlabel {}\nset ylabel {}\nset title {}\n{}\n",
      quote(timed ? "cost: seconds of computing per simulated second (median of repeats)"
                  : "dt (s)"),
      quote(metric_label(metric)),
      quote(results.scene->name + ": work-precision over the dt sweep (each marker one dt)"), plot);
  return draw(script, data, batch, name);
}

/// Each backend's largest position distance from the reference over the bodies, against
/// time: where the methods part from the reference, and when (a bounce shows as a jump).
std::string error_plot(const CaseResults& results, FileBatch& batch, const std::string& name) {
  const Trajectory& reference = results.reference_run.trajectory;
  if (reference.states.empty())
    return "no plot of the distance from the reference: " + results.reference_run.reason;
  const auto runs = report_runs(results);
  std::string data, plot;
  int block = 0;
  for (std::size_t i = 1; i < runs.size(); ++i) {
    // Measured in the run's child against the reference (run_summary.hpp).
    const RunRecord& run = *runs[i];
    std::vector<double> times, distance;
    for (std::size_t j = 0; j < run.distance.size() && j < run.trajectory.times.size(); ++j) {
      // A log axis cannot show 0: such points are left out.
      if (!(run.distance[j] > 0.0) || !std::isfinite(run.distance[j])) continue;
      times.push_back(run.trajectory.times[j]);
      distance.push_back(run.distance[j]);
    }
    if (distance.empty()) continue;
    data += "# " + run.backend + "\n" + series_rows(times, distance) + "\n\n";
    plot += (plot.empty() ? "plot " : ", \\\n     ") + series_line(i, block++, run.backend);
  }
  if (plot.empty()) return "no backend has a trajectory to compare with the reference";
  const std::string script = fmt::format(
      "set grid\nset logscale y\nset format y \"%.0e\"\nset key outside right top\n"
      "set xlabel \"t (s)\"\nset ylabel \"largest position distance from the reference (m)\"\n"
      "set title {}\n{}\n",
      quote(results.scene->name + ": distance from the reference at report_dt"), plot);
  return draw(script, data, batch, name);
}

std::string work_precision_file(const Scene& scene, const std::string& metric) {
  std::string file = scene.name + "-work-precision-" + metric + ".svg";
  for (char& c : file)
    if (c == '/') c = '-';
  return file;
}

}  // namespace

bool draws_speed(const Scene& scene) {
  if (!scene.air || !(scene.air->density > 0.0)) return false;
  for (const Body& b : scene.bodies)
    if (b.drag_coefficient > 0.0) return true;
  return false;
}

std::vector<std::string> plot_file_names(const Scene& scene) {
  std::vector<std::string> names;
  for (const std::string& metric : scene.report.metrics)
    names.push_back(work_precision_file(scene, metric));
  for (const char* kind : {"-trajectory.svg", "-energy.svg", "-error.svg"})
    names.push_back(scene.name + kind);
  if (draws_speed(scene)) names.push_back(scene.name + "-speed.svg");
  if (!stopping_bodies(scene).empty()) names.push_back(scene.name + "-stop.svg");
  if (!turning_bodies(scene).empty()) names.push_back(scene.name + "-rotation.svg");
  if (scene.sweep && !scene.second_sweep) names.push_back(scene.name + "-sweep.svg");
  // A map's pictures: the small multiples and one per backend that can run the case.
  if (scene.second_sweep) {
    names.push_back(map_multiples_file(scene));
    names.push_back(map_differences_file(scene));
    for (std::size_t k = 0; k < scene.claims.size(); ++k)
      if (scene.claims[k].region) names.push_back(map_claim_file(scene, k));
    for (const std::string& backend : runnable_backend_names(scene, engine_catalogue()))
      names.push_back(map_file(scene, backend));
  }
  for (const char* kind : {"-motion.svg", "-motion-still.svg"}) names.push_back(scene.name + kind);
  return names;
}

/// The motion view and its still, which need no gnuplot: written by the program itself.
void write_motion(const CaseResults& results, FileBatch& batch, PlotFiles& files) {
  const Scene& scene = *results.scene;
  const std::vector<int> drawn = drawn_bodies(scene);
  const std::string motion = motion_svg(results, drawn);
  if (motion.empty()) {
    files.note += std::string(files.note.empty() ? "" : "; ") + "no motion view: no run has states";
    return;
  }
  files.motion = scene.name + "-motion.svg";
  batch.write(files.motion, motion);
  files.still = scene.name + "-motion-still.svg";
  batch.write(files.still, motion_still_svg(results, drawn, still_instants(scene)));
}

/// A map's pictures, which need no gnuplot: written by the program itself.
void write_map(const CaseResults& results, FileBatch& batch, PlotFiles& files) {
  if (!results.sweep || results.sweep->second_parameter.empty()) return;
  const Scene& scene = *results.scene;
  files.map.multiples = map_multiples_file(scene);
  batch.write(files.map.multiples, map_multiples_svg(results));
  if (const std::string differs = map_differences_svg(results); !differs.empty()) {
    files.map.differs = map_differences_file(scene);
    batch.write(files.map.differs, differs);
  }
  for (const std::string& backend : map_backends(results)) {
    files.map.backends.push_back({backend, map_file(scene, backend)});
    batch.write(files.map.backends.back().second, map_svg(results, backend));
  }
  // Each map's claim drawn: its backend's map with the points where it failed crossed out.
  for (const ClaimResult& c : results.claims)
    if (c.claim->region)
      batch.write(map_claim_file(scene, static_cast<std::size_t>(c.claim - scene.claims.data())),
                  map_claim_svg(results, c));
}

PlotFiles write_plots(const CaseResults& results, FileBatch& batch) {
  PlotFiles files;
  write_motion(results, batch, files);
  write_map(results, batch, files);
  if (!gnuplot_available()) {
    files.note +=
        std::string(files.note.empty() ? "" : "; ") + "plots skipped: " + gnuplot_problem();
    return files;
  }
  const Scene& scene = *results.scene;
  const auto attempt = [&](const std::string& file, const std::string& error) {
    if (!error.empty()) files.note += (files.note.empty() ? "" : "; ") + file + ": " + error;
    return error.empty();
  };
  for (const std::string& metric : scene.report.metrics)
    if (const std::string file = work_precision_file(scene, metric);
        attempt(file, work_precision_plot(results, metric, batch, file)))
      files.work_precision.push_back({metric, file});
  if (const std::string file = scene.name + "-trajectory.svg";
      attempt(file, bodies_plot(results, batch, file, false)))
    files.trajectory = file;
  if (const std::string file = scene.name + "-speed.svg";
      draws_speed(scene) && attempt(file, bodies_plot(results, batch, file, true)))
    files.speed = file;
  if (const std::string file = scene.name + "-energy.svg";
      attempt(file, energy_plot(results, batch, file)))
    files.energy = file;
  if (const std::string file = scene.name + "-error.svg";
      attempt(file, error_plot(results, batch, file)))
    files.error = file;
  if (const std::string file = scene.name + "-stop.svg";
      !stopping_bodies(scene).empty() && attempt(file, stop_plot(results, batch, file)))
    files.stop = file;
  if (const std::string file = scene.name + "-rotation.svg";
      !turning_bodies(scene).empty() && attempt(file, rotation_plot(results, batch, file)))
    files.rotation = file;
  if (const std::string file = scene.name + "-sweep.svg";
      results.sweep && results.sweep->second_parameter.empty() &&
      attempt(file, sweep_plot(results, batch, file)))
    files.sweep = file;
  return files;
}

}  // namespace bb
