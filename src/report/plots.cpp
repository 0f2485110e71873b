#include "report/plots.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <signal.h>
#include <stdlib.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cctype>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "report/work_precision.hpp"
#include "run/run_summary.hpp"

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

/// Whether `path` holds a whole SVG document (gnuplot may exit 0 on a full disk).
bool complete_svg(const std::string& path) {
  std::ifstream in(path, std::ios::binary | std::ios::ate);
  const std::streamoff size = in.tellg();
  if (!in || size < 7) return false;
  in.seekg(std::max<std::streamoff>(0, size - 64));
  const std::string tail((std::istreambuf_iterator<char>(in)), {});
  return tail.find("</svg>") != std::string::npos;
}

/// Runs gnuplot on `script` with its stderr into `log` and waits: "" when it succeeded,
/// else how it ended. No shell stands between (a path may hold any character), and gnuplot
/// dies with this process, like the children of the pool.
std::string run_gnuplot(const std::string& script, const std::string& log) {
  std::fflush(nullptr);
  const pid_t parent = getpid();
  const pid_t pid = fork();
  if (pid < 0) return std::string("cannot start gnuplot: ") + std::strerror(errno);
  if (pid == 0) {
    prctl(PR_SET_PDEATHSIG, SIGKILL);
    if (getppid() != parent) _exit(127);
    const int fd = open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    if (fd >= 0) dup2(fd, STDERR_FILENO);
    execlp("gnuplot", "gnuplot", script.c_str(), static_cast<char*>(nullptr));
    _exit(127);
  }
  int status = 0;
  while (waitpid(pid, &status, 0) < 0)
    if (errno != EINTR) return std::string("cannot wait for gnuplot: ") + std::strerror(errno);
  if (WIFEXITED(status) && WEXITSTATUS(status) == 0) return "";
  return WIFEXITED(status) ? "exit " + std::to_string(WEXITSTATUS(status))
                           : "killed by signal " + std::to_string(WTERMSIG(status));
}

/// Runs `script` (which reads `data`) and writes the SVG as `name` into `batch`. Returns
/// an error for a plot there is nothing to draw; throws WriteError when a file could not be
/// written.
std::string draw(const std::string& script_body, const std::string& data, FileBatch& batch,
                 const std::string& name, int height = 600) {
  // gnuplot's script and data sit beside the SVG under a temporary name: if this process
  // is killed, the next run removes them with the other temporaries of dead processes.
  const fs::path temp = batch.folder() + "/" + name + ".plot" + temporary_suffix();
  std::error_code ec;
  fs::remove_all(temp, ec);
  if (!fs::create_directory(temp, ec))
    throw WriteError(temp.string(), ec ? ec.message() : std::string("it exists"));
  // The temporary folder goes, whatever happens.
  struct Cleanup {
    fs::path path;
    ~Cleanup() {
      std::error_code ec;
      fs::remove_all(path, ec);
    }
  } cleanup{temp};
  const std::string output = batch.path_for(name);
  write_whole_file((temp / "data.txt").string(), data);
  write_whole_file((temp / "plot.gp").string(),
                   terminal(height) + "set output " + quote(output) + "\n" +
                       "data = " + quote((temp / "data.txt").string()) + "\n" + script_body);
  const std::string ended = run_gnuplot((temp / "plot.gp").string(), (temp / "log.txt").string());
  if (!ended.empty() || !complete_svg(output)) {
    std::ifstream log(temp / "log.txt");
    std::string said(std::istreambuf_iterator<char>(log), {});
    while (!said.empty() && std::isspace(static_cast<unsigned char>(said.back()))) said.pop_back();
    std::remove(output.c_str());
    throw WriteError(batch.folder() + "/" + name,
                     !ended.empty()
                         ? "gnuplot failed (" + ended + ")" + (said.empty() ? "" : ": " + said)
                         : "gnuplot left an incomplete SVG (is the disk full?)");
  }
  return "";
}

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
  return draw(script, data, batch, name);
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
    const double v[3] = {s[body].position.x(), s[body].position.y(), s[body].position.z()};
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

/// The rows "t value" of one series, thinned for drawing.
std::string series_rows(const std::vector<double>& times, const std::vector<double>& values) {
  std::string rows;
  for (std::size_t j : thinned(values, kMaxPlotPoints))
    rows += fmt::format("{:.9g} {:.9g}\n", times[j], values[j]);
  return rows;
}

std::string trajectory_plot(const CaseResults& results, FileBatch& batch, const std::string& name) {
  const Scene& scene = *results.scene;
  const auto runs = report_runs(results);
  const std::size_t shown = std::min(scene.bodies.size(), kPlottedBodies);
  // One legend, beside the first panel; every panel keeps the same right margin to line up.
  std::string data,
      script = fmt::format(
          "set multiplot layout {},1 title {}\nset grid\nset rmargin at screen 0.70\n"
          "set key at screen 0.99, screen 0.92 right top maxrows 20 samplen 2 font \",10\"\n",
          shown, quote(scene.name + ": main coordinate of each body at report_dt"));
  int block = 0;
  for (std::size_t b = 0; b < shown; ++b) {
    // The reference decides the axis; without one, the first run that has states.
    const Trajectory* guide = &results.reference_run.trajectory;
    for (const RunRecord* r : runs)
      if (guide->states.empty()) guide = &r->trajectory;
    const int axis = main_axis(*guide, b);
    const char* axis_name = axis == 0 ? "x" : axis == 1 ? "y" : "z";
    std::string plot;
    for (std::size_t i = 0; i < runs.size(); ++i) {
      const Trajectory& t = runs[i]->trajectory;
      // A run without states (a reference with no answer) draws nothing.
      if (t.states.empty()) continue;
      data += "# " + runs[i]->backend + "\n";
      std::vector<double> coordinate;
      for (const State& s : t.states)
        coordinate.push_back(axis == 0   ? s[b].position.x()
                             : axis == 1 ? s[b].position.y()
                                         : s[b].position.z());
      data += series_rows(t.times, coordinate) + "\n\n";
      plot += (plot.empty() ? "plot " : ", \\\n     ") + series_line(i, block++, runs[i]->backend);
    }
    script += fmt::format("set xlabel \"t (s)\"\nset ylabel {}\n{}\nunset key\n",
                          quote(scene.bodies[b].name + " " + axis_name + " (m)"), plot);
  }
  return draw(script + "unset multiplot\n", data, batch, name, 80 + 240 * static_cast<int>(shown));
}

std::string energy_plot(const CaseResults& results, FileBatch& batch, const std::string& name) {
  const Scene& scene = *results.scene;
  const auto runs = report_runs(results);
  std::string data, plot;
  int block = 0;
  for (std::size_t i = 0; i < runs.size(); ++i) {
    // Each run's energy at every sample, measured where the run was (run_summary.hpp).
    const RunRecord& run = *runs[i];
    if (run.energy.empty()) continue;
    data += "# " + run.backend + "\n" + series_rows(run.trajectory.times, run.energy) + "\n\n";
    plot += (plot.empty() ? "plot " : ", \\\n     ") + series_line(i, block++, run.backend);
  }
  const std::string script = fmt::format(
      "set grid\nset key outside right top\nset xlabel \"t (s)\"\n"
      "set ylabel \"total energy (J): kinetic + rotational + gravitational\"\nset title {}\n{}\n",
      quote(scene.name + ": energy at report_dt"), plot);
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
      if (run.distance[j] <= 0.0) continue;
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

}  // namespace

std::vector<std::size_t> thinned(const std::vector<double>& values, std::size_t max_points) {
  const std::size_t n = values.size();
  std::vector<std::size_t> keep;
  if (n <= max_points || max_points < 4) {
    for (std::size_t j = 0; j < n; ++j) keep.push_back(j);
    return keep;
  }
  // Buckets of equal width; each gives its lowest and highest point, in time order.
  const std::size_t buckets = max_points / 2 - 1;
  keep.push_back(0);
  for (std::size_t k = 0; k < buckets; ++k) {
    const std::size_t from = 1 + k * (n - 2) / buckets, to = 1 + (k + 1) * (n - 2) / buckets;
    if (from >= to) continue;
    std::size_t low = from, high = from;
    for (std::size_t j = from; j < to; ++j) {
      if (values[j] < values[low]) low = j;
      if (values[j] > values[high]) high = j;
    }
    keep.push_back(std::min(low, high));
    if (low != high) keep.push_back(std::max(low, high));
  }
  keep.push_back(n - 1);
  return keep;
}

namespace {

std::string work_precision_file(const Scene& scene, const std::string& metric) {
  std::string file = scene.name + "-work-precision-" + metric + ".svg";
  for (char& c : file)
    if (c == '/') c = '-';
  return file;
}

}  // namespace

std::vector<std::string> plot_file_names(const Scene& scene) {
  std::vector<std::string> names;
  for (const std::string& metric : scene.report.metrics)
    names.push_back(work_precision_file(scene, metric));
  for (const char* kind : {"-trajectory.svg", "-energy.svg", "-error.svg"})
    names.push_back(scene.name + kind);
  return names;
}

PlotFiles write_plots(const CaseResults& results, FileBatch& batch) {
  PlotFiles files;
  if (!gnuplot_available()) {
    files.note = "plots skipped: gnuplot was not found (install gnuplot-nox)";
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
      attempt(file, trajectory_plot(results, batch, file)))
    files.trajectory = file;
  if (const std::string file = scene.name + "-energy.svg";
      attempt(file, energy_plot(results, batch, file)))
    files.energy = file;
  if (const std::string file = scene.name + "-error.svg";
      attempt(file, error_plot(results, batch, file)))
    files.error = file;
  return files;
}

}  // namespace bb
