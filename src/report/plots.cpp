#include "report/plots.hpp"

#include <fmt/format.h>
#include <stdlib.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>

#include "report/work_precision.hpp"
#include "scene/motion.hpp"

namespace bb {

namespace {

namespace fs = std::filesystem;

/// A fixed colour per series position, so a backend keeps its colour across plots.
const char* kColours[] = {"#1f77b4", "#ff7f0e", "#2ca02c", "#d62728", "#9467bd",
                          "#8c564b", "#e377c2", "#17becf", "#bcbd22", "#7f7f7f"};

std::string colour(std::size_t i) {
  return kColours[i % (sizeof(kColours) / sizeof(kColours[0]))];
}

std::string quote(const std::string& s) {
  std::string out = "\"";
  for (char c : s) out += (c == '"' || c == '\\') ? std::string("\\") + c : std::string(1, c);
  return out + "\"";
}

std::string terminal(int height) {
  return fmt::format(
      "set terminal svg size 960,{} noenhanced font \"sans,12\" background \"white\"\n", height);
}

bool gnuplot_available() {
  static const bool available = std::system("gnuplot --version > /dev/null 2>&1") == 0;
  return available;
}

/// Runs `script` (which reads `data`) and moves the SVG into `target`. Returns an error, or "".
std::string draw(const std::string& script_body, const std::string& data, const std::string& target,
                 int height = 600) {
  char folder_template[] = "/tmp/beachball-plot-XXXXXX";
  const char* folder = mkdtemp(folder_template);
  if (folder == nullptr) return "cannot make a temporary folder";
  const fs::path temp(folder);
  const std::string partial = target + ".tmp." + std::to_string(getpid());
  std::ofstream(temp / "data.txt") << data;
  std::ofstream(temp / "plot.gp") << terminal(height) << "set output " << quote(partial) << "\n"
                                  << "data = " << quote((temp / "data.txt").string()) << "\n"
                                  << script_body;
  const std::string command =
      "gnuplot " + (temp / "plot.gp").string() + " 2> " + (temp / "log.txt").string();
  const int status = std::system(command.c_str());
  std::string error;
  if (status != 0) {
    std::ifstream log(temp / "log.txt");
    error = "gnuplot failed: " + std::string(std::istreambuf_iterator<char>(log), {});
    std::remove(partial.c_str());
  } else {
    std::error_code ec;
    fs::rename(partial, target, ec);
    if (ec) error = "cannot move " + partial + ": " + ec.message();
  }
  fs::remove_all(temp);
  return error;
}

std::string metric_label(const std::string& metric) {
  if (metric.starts_with("position")) return metric + " (m)";
  if (metric == "velocity_max") return metric + " (m/s)";
  if (metric == "energy_max") return metric + " (relative)";
  return "|" + metric + " - reference|";
}

std::string work_precision_plot(const CaseResults& results, const std::string& metric,
                                const std::string& target) {
  const std::vector<WorkSeries> series = work_series(results, metric);
  const bool timed =
      !series.empty() && !series.front().points.empty() && series.front().points.front().cost;
  std::string data, plot;
  int block = 0;
  for (std::size_t i = 0; i < series.size(); ++i) {
    std::string rows;
    for (const WorkPoint& p : series[i].points)
      if (p.error > 0.0) rows += fmt::format("{:.17g} {:.17g}\n", timed ? *p.cost : p.dt, p.error);
    if (rows.empty()) continue;
    data += "# " + series[i].backend + "\n" + rows + "\n\n";
    plot += fmt::format(
        "{}data index {} using 1:2 with linespoints lw 2 pt {} ps 1.2 lc rgb \"{}\" title {}",
        plot.empty() ? "plot " : ", \\\n     ", block++, 1 + i % 13, colour(i),
        quote(series[i].backend));
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
  return draw(script, data, target);
}

/// Runs at report_dt that produced samples, the reference first.
std::vector<const RunRecord*> report_runs(const CaseResults& results) {
  std::vector<const RunRecord*> out = {&results.reference_run};
  for (const RunRecord& run : results.runs)
    if (run.dt && *run.dt == results.scene->report_dt && !run.trajectory.states.empty())
      out.push_back(&run);
  return out;
}

/// The axis (0, 1, 2) along which the reference moves `body` the most.
int main_axis(const Trajectory& reference, std::size_t body) {
  double lo[3] = {1e300, 1e300, 1e300}, hi[3] = {-1e300, -1e300, -1e300};
  for (const State& s : reference.states) {
    const double v[3] = {s[body].position.x, s[body].position.y, s[body].position.z};
    for (int a = 0; a < 3; ++a) lo[a] = std::min(lo[a], v[a]), hi[a] = std::max(hi[a], v[a]);
  }
  int best = 1;
  for (int a = 0; a < 3; ++a)
    if (hi[a] - lo[a] > hi[best] - lo[best] + 1e-12) best = a;
  return best;
}

std::string series_line(std::size_t i, int block, const std::string& title) {
  // The reference is drawn thick and black under the backends.
  if (i == 0)
    return fmt::format("data index {} using 1:2 with lines lw 4 lc rgb \"black\" title {}", block,
                       quote(title));
  return fmt::format(
      "data index {} using 1:2 with linespoints lw 1.5 pt {} ps 0.6 pi 6 lc rgb \"{}\" title {}",
      block, i % 13, colour(i - 1), quote(title));
}

std::string trajectory_plot(const CaseResults& results, const std::string& target) {
  const Scene& scene = *results.scene;
  const auto runs = report_runs(results);
  const std::size_t shown = std::min<std::size_t>(scene.bodies.size(), 6);
  // One legend, beside the first panel; every panel keeps the same right margin to line up.
  std::string data,
      script = fmt::format(
          "set multiplot layout {},1 title {}\nset grid\nset rmargin at screen 0.70\n"
          "set key at screen 0.99, screen 0.92 right top maxrows 20 samplen 2 font \",10\"\n",
          shown, quote(scene.name + ": main coordinate of each body at report_dt"));
  int block = 0;
  for (std::size_t b = 0; b < shown; ++b) {
    const int axis = main_axis(results.reference_run.trajectory, b);
    const char* axis_name = axis == 0 ? "x" : axis == 1 ? "y" : "z";
    std::string plot;
    for (std::size_t i = 0; i < runs.size(); ++i) {
      data += "# " + runs[i]->backend + "\n";
      const Trajectory& t = runs[i]->trajectory;
      for (std::size_t j = 0; j < t.states.size(); ++j) {
        const Vec3& p = t.states[j][b].position;
        data += fmt::format("{:.17g} {:.17g}\n", t.times[j],
                            axis == 0   ? p.x
                            : axis == 1 ? p.y
                                        : p.z);
      }
      data += "\n\n";
      plot += (plot.empty() ? "plot " : ", \\\n     ") + series_line(i, block++, runs[i]->backend);
    }
    script += fmt::format("set xlabel \"t (s)\"\nset ylabel {}\n{}\nunset key\n",
                          quote(scene.bodies[b].name + " " + axis_name + " (m)"), plot);
  }
  return draw(script + "unset multiplot\n", data, target, 80 + 240 * static_cast<int>(shown));
}

std::string energy_plot(const CaseResults& results, const std::string& target) {
  const Scene& scene = *results.scene;
  const auto runs = report_runs(results);
  std::string data, plot;
  for (std::size_t i = 0; i < runs.size(); ++i) {
    data += "# " + runs[i]->backend + "\n";
    const Trajectory& t = runs[i]->trajectory;
    for (std::size_t j = 0; j < t.states.size(); ++j)
      data += fmt::format("{:.17g} {:.17g}\n", t.times[j], total_energy(scene, t.states[j]));
    data += "\n\n";
    plot += (plot.empty() ? "plot " : ", \\\n     ") +
            series_line(i, static_cast<int>(i), runs[i]->backend);
  }
  const std::string script = fmt::format(
      "set grid\nset key outside right top\nset xlabel \"t (s)\"\n"
      "set ylabel \"total energy (J): kinetic + rotational + gravitational\"\nset title {}\n{}\n",
      quote(scene.name + ": energy at report_dt"), plot);
  return draw(script, data, target);
}

}  // namespace

PlotFiles write_plots(const CaseResults& results, const std::string& dir) {
  PlotFiles files;
  if (!gnuplot_available()) {
    files.note = "plots skipped: gnuplot was not found (install gnuplot-nox)";
    return files;
  }
  const std::string name = results.scene->name;
  const auto attempt = [&](const std::string& file, const std::string& error) {
    if (!error.empty()) files.note += (files.note.empty() ? "" : "; ") + file + ": " + error;
    return error.empty();
  };
  for (const std::string& metric : results.scene->report.metrics) {
    std::string file = name + "-work-precision-" + metric + ".svg";
    for (char& c : file)
      if (c == '/') c = '-';
    if (attempt(file, work_precision_plot(results, metric, (fs::path(dir) / file).string())))
      files.work_precision.push_back({metric, file});
  }
  if (const std::string file = name + "-trajectory.svg";
      attempt(file, trajectory_plot(results, (fs::path(dir) / file).string())))
    files.trajectory = file;
  if (const std::string file = name + "-energy.svg";
      attempt(file, energy_plot(results, (fs::path(dir) / file).string())))
    files.energy = file;
  return files;
}

}  // namespace bb
