#include "report/gnuplot.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <signal.h>
#include <stdlib.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <optional>

#include "files/whole_file.hpp"
#include "report/backend_style.hpp"
#include "report/plot_layout.hpp"
#include "run/interrupt.hpp"

namespace bb {

namespace {

namespace fs = std::filesystem;

}  // namespace

std::string quote(const std::string& s) {
  std::string out = "\"";
  for (char c : s) out += (c == '"' || c == '\\') ? std::string("\\") + c : std::string(1, c);
  return out + "\"";
}

namespace {

std::string terminal(int height) {
  return fmt::format(
      "set terminal svg size {},{} noenhanced font \"sans,12\" background \"white\"\n", kPlotWidth,
      height);
}

}  // namespace

namespace {

/// What `gnuplot --version` gave: what it printed when it ran, else why it did not (not
/// found, or found and failed to start, with how it ended and what it said).
struct GnuplotProbe {
  std::optional<std::string> version;
  std::string problem;
};

/// Ends `text` at its last printing character.
std::string trimmed(std::string text) {
  while (!text.empty() && std::isspace(static_cast<unsigned char>(text.back()))) text.pop_back();
  return text;
}

/// Runs `gnuplot --version` without a shell, its stdout and stderr read back; a second pipe,
/// closed by a successful exec, brings back exec's errno when there is no gnuplot to run.
GnuplotProbe probe_gnuplot() {
  int output[2], exec_error[2];
  if (pipe(output) != 0)
    return {std::nullopt, std::string("cannot start gnuplot: ") + std::strerror(errno)};
  if (pipe2(exec_error, O_CLOEXEC) != 0) {
    close(output[0]), close(output[1]);
    return {std::nullopt, std::string("cannot start gnuplot: ") + std::strerror(errno)};
  }
  std::fflush(nullptr);
  const pid_t parent = getpid();
  const pid_t pid = fork();
  if (pid == 0) {
    prctl(PR_SET_PDEATHSIG, SIGKILL);
    if (getppid() != parent) _exit(127);
    dup2(output[1], STDOUT_FILENO);
    dup2(output[1], STDERR_FILENO);
    execlp("gnuplot", "gnuplot", "--version", static_cast<char*>(nullptr));
    const int error = errno;
    if (write(exec_error[1], &error, sizeof error) < 0) _exit(127);
    _exit(127);
  }
  close(output[1]), close(exec_error[1]);
  if (pid < 0) {
    close(output[0]), close(exec_error[0]);
    return {std::nullopt, std::string("cannot start gnuplot: ") + std::strerror(errno)};
  }
  std::string said;
  char buffer[256];
  for (ssize_t n; (n = read(output[0], buffer, sizeof buffer)) != 0;)
    if (n > 0)
      said.append(buffer, static_cast<std::size_t>(n));
    else if (errno != EINTR)
      break;
  int error = 0;
  const bool exec_failed = read(exec_error[0], &error, sizeof error) == sizeof error;
  close(output[0]), close(exec_error[0]);
  int status = 0;
  while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  if (exec_failed)
    return {std::nullopt, error == ENOENT
                              ? "gnuplot was not found (install gnuplot-nox)"
                              : std::string("gnuplot could not be run: ") + std::strerror(error)};
  if (WIFEXITED(status) && WEXITSTATUS(status) == 0) return {said, ""};
  const std::string ended = WIFEXITED(status)
                                ? "exit " + std::to_string(WEXITSTATUS(status))
                                : "killed by signal " + std::to_string(WTERMSIG(status));
  said = trimmed(said);
  return {std::nullopt, "gnuplot failed to start (gnuplot --version: " + ended + ")" +
                            (said.empty() ? "" : ": " + said)};
}

/// The probe, made once: a kept drawing's key holds the version.
const GnuplotProbe& gnuplot_probe() {
  static const GnuplotProbe probe = probe_gnuplot();
  return probe;
}

/// What `gnuplot --version` prints, or nullopt when it cannot run: part of a kept drawing's
/// key.
const std::optional<std::string>& gnuplot_version() {
  return gnuplot_probe().version;
}

/// The cache draw() keeps its drawings in, while a KeptDrawings lives.
const ResultCache* drawings_cache = nullptr;
bool reuse_drawings = false;

}  // namespace

KeptDrawings::KeptDrawings(const ResultCache* cache, bool reuse)
    : previous_cache_(drawings_cache), previous_reuse_(reuse_drawings) {
  drawings_cache = cache, reuse_drawings = reuse;
}

KeptDrawings::~KeptDrawings() {
  drawings_cache = previous_cache_, reuse_drawings = previous_reuse_;
}

bool gnuplot_available() {
  return gnuplot_version().has_value();
}

std::string gnuplot_problem() {
  return gnuplot_probe().problem;
}

namespace {

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
  while (waitpid(pid, &status, 0) < 0) {
    if (errno != EINTR) return std::string("cannot wait for gnuplot: ") + std::strerror(errno);
    // A signal that stops the program need not wait for the drawing.
    if (interrupt_signal() != 0) kill(pid, SIGKILL);
  }
  if (WIFEXITED(status) && WEXITSTATUS(status) == 0) return "";
  // Its SVG grew past this process's file size limit (which it inherits): the program's own
  // stop, as if its own write had (interrupt.hpp).
  if (WIFSIGNALED(status) && WTERMSIG(status) == SIGXFSZ) raise(SIGXFSZ);
  return WIFEXITED(status) ? "exit " + std::to_string(WEXITSTATUS(status))
                           : "killed by signal " + std::to_string(WTERMSIG(status));
}

}  // namespace

std::string draw(const std::string& script_body, const std::string& data, FileBatch& batch,
                 const std::string& name, int height) {
  // A signal stops the drawing between two plots, and gnuplot's failure when the signal
  // killed it too is the signal's stop, not a failure of its own.
  stop_if_interrupted(name);
  // The SVG holds no path: the same script, data, size and gnuplot draw the same bytes.
  const std::string key = drawings_cache ? digest("drawing\n" + gnuplot_version().value_or("") +
                                                  terminal(height) + script_body + "\n" + data)
                                         : "";
  if (const auto kept =
          reuse_drawings && drawings_cache ? drawings_cache->load(key) : std::nullopt) {
    batch.write(name, *kept);
    return "";
  }
  // gnuplot's script and data sit in the batch's own temporary folder, gone with it.
  const fs::path temp = batch.work_folder(name + ".plot");
  const std::string output = batch.path_for(name);
  write_whole_file((temp / "data.txt").string(), data);
  write_whole_file((temp / "plot.gp").string(),
                   terminal(height) + "set output " + quote(output) + "\n" +
                       "data = " + quote((temp / "data.txt").string()) + "\n" + script_body);
  const std::string ended = run_gnuplot((temp / "plot.gp").string(), (temp / "log.txt").string());
  stop_if_interrupted(name);
  if (!ended.empty() || !complete_svg(output)) {
    const std::string said = trimmed(read_whole_file((temp / "log.txt").string()).value_or(""));
    std::remove(output.c_str());
    throw WriteError(batch.folder() + "/" + name,
                     !ended.empty()
                         ? "gnuplot failed (" + ended + ")" + (said.empty() ? "" : ": " + said)
                         : "gnuplot left an incomplete SVG (is the disk full?)");
  }
  // Kept only when read back whole: an empty drawing would be served as the picture later.
  if (drawings_cache)
    if (const std::optional<std::string> svg = read_whole_file(output))
      drawings_cache->store(key, *svg);
  return "";
}

std::vector<const RunRecord*> report_runs(const CaseResults& results) {
  std::vector<const RunRecord*> out = {&results.reference_run};
  for (const RunRecord& run : results.runs)
    if (run.dt && *run.dt == results.scene->report_dt && !run.trajectory.states.empty())
      out.push_back(&run);
  return out;
}

std::string series_style(std::size_t i, const std::string& backend) {
  // One colour per backend on every plot of the report; the reference thick and black,
  // the course methods solid, the engines dashed (backend_style.hpp).
  const BackendStyle style = backend_style(backend);
  if (style.kind == LineKind::Reference) return "with lines lw 4 lc rgb \"black\"";
  return fmt::format("with linespoints lw 1.5 dt {} pt {} ps 0.6 pi 6 lc rgb \"{}\"",
                     style.kind == LineKind::Engine ? 2 : 1, i % 13, style.colour);
}

std::string series_line(std::size_t i, int block, const std::string& backend, bool titled) {
  return fmt::format("data index {} using 1:2 {} {}", block, series_style(i, backend),
                     titled ? "title " + quote(backend) : "notitle");
}

std::string series_rows(const std::vector<double>& times, const std::vector<double>& values) {
  // gnuplot cannot draw an infinity or a NaN (a panel of nothing else ends its plot): such
  // points are left out, and a series of nothing else is empty.
  std::vector<double> t, v;
  for (std::size_t j = 0; j < times.size() && j < values.size(); ++j)
    if (std::isfinite(times[j]) && std::isfinite(values[j])) {
      t.push_back(times[j]);
      v.push_back(values[j]);
    }
  std::string rows;
  for (std::size_t j : thinned(v, kMaxPlotPoints))
    rows += fmt::format("{:.9g} {:.9g}\n", t[j], v[j]);
  return rows;
}

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

void TwoColumnPlot::add(bool right, std::size_t i, const std::string& backend,
                        const std::vector<double>& times, const std::vector<double>& values) {
  const std::string rows = series_rows(times, values);
  if (rows.empty()) return;
  data_ += "# " + backend + "\n" + rows + "\n\n";
  std::string& plot = right ? right_ : left_;
  plot += (plot.empty() ? "plot " : ", \\\n     ") + series_line(i, block_++, backend);
  if (!right) left_titles_.push_back({backend, series_style(i, backend)});
}

void TwoColumnPlot::end_row(const std::string& left_label, const std::string& right_label,
                            const Window& left_window, const Window& right_window) {
  if (!left_.empty() && !right_.empty()) {
    // The legend is the first row's left panel's.
    if (rows_.empty()) legend_ = left_titles_;
    rows_.push_back({left_label, right_label, left_, right_, left_window, right_window});
  }
  left_.clear();
  right_.clear();
  left_titles_.clear();
}

std::string TwoColumnPlot::draw_into(FileBatch& batch, const std::string& name) const {
  if (rows_.empty()) return "no run at report_dt has states to draw";
  // The columns share what the legend's band leaves: each panel's tic labels left of it, its
  // name above it (wrapped to its width: a long name on the side of a panel ran into the
  // next row and the other column).
  const LegendBand band = legend_band(legend_, 40);
  constexpr double kLeft = 0.08, kGap = 0.09, kNameFont = 11.0;
  const double width = (band.panels_right - kLeft - kGap) / 2.0;
  const double right_left = kLeft + width + kGap;
  const auto panel_name = [&](const std::string& label) {
    return quote_lines(wrapped(label, width * kPlotWidth, kNameFont));
  };
  const int height = std::max(80 + 260 * static_cast<int>(rows_.size()), band.height + 60);
  // A panel's vertical axis: its window, else its own data's.
  const auto y_axis = [](const Window& w) {
    return w ? fmt::format("set yrange [{:.9g}:{:.9g}]\n", w->first, w->second)
             : std::string("set autoscale y\n");
  };
  std::string script =
      x_range_ ? fmt::format("set xrange [{:.9g}:{:.9g}]\n", x_range_->first, x_range_->second)
               : "";
  for (const Row& row : rows_)
    script += fmt::format(
        "set lmargin at screen {:.4f}\nset rmargin at screen {:.4f}\nset xlabel {}\n"
        "set title {} font \",{}\"\n{}{}\n"
        "set lmargin at screen {:.4f}\nset rmargin at screen {:.4f}\nset title {} font "
        "\",{}\"\n{}{}\n",
        kLeft, kLeft + width, quote(x_label_), panel_name(row.left_label), kNameFont,
        y_axis(row.left_window), row.left, right_left, band.panels_right,
        panel_name(row.right_label), kNameFont, y_axis(row.right_window), row.right);
  const std::string page = fmt::format(
      "set multiplot layout {},2 title {}\nset grid\nset clip two\nunset key\n{}{}unset "
      "multiplot\n",
      rows_.size(), quote_lines(wrapped(title_, kPlotWidth - 60, 12.0)), script, band.plot(height));
  return draw(page, data_, batch, name, height);
}

}  // namespace bb
