#include "report/energy_plot.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <utility>

#include "report/gnuplot.hpp"
#include "report/plot_layout.hpp"

namespace bb {

namespace {

/// The energy axis's window when some runs leave the others far behind (an exploding
/// method at 26,000 J beside a spring's 10 J): the runs whose largest distance from the
/// start energy is more than kOffScale times the typical run's, or than the start energy,
/// are clipped, and named with the most they reach.
struct EnergyWindow {
  double low = 0.0, high = 0.0;
  std::vector<std::string> clipped;  ///< "course/explicit-euler (reaches 2.65e+04 J)", ...
};

constexpr double kOffScale = 20.0;

std::optional<EnergyWindow> energy_window(const std::vector<const RunRecord*>& runs) {
  const auto finite_range = [](const std::vector<double>& e) {
    double lo = 1e300, hi = -1e300;
    for (double v : e)
      if (std::isfinite(v)) lo = std::min(lo, v), hi = std::max(hi, v);
    return std::pair{lo, hi};
  };
  // The start energy: the first run's (the reference's when it has one) first finite value.
  std::optional<double> start;
  for (const RunRecord* r : runs)
    for (double v : r->energy)
      if (!start && std::isfinite(v)) start = v;
  if (!start) return std::nullopt;
  std::vector<double> reach;
  for (const RunRecord* r : runs) {
    const auto [lo, hi] = finite_range(r->energy);
    if (lo <= hi) reach.push_back(std::max(std::abs(lo - *start), std::abs(hi - *start)));
  }
  std::vector<double> sorted = reach;
  std::sort(sorted.begin(), sorted.end());
  const double typical = sorted[sorted.size() / 2];
  const double limit = kOffScale * std::max({typical, std::abs(*start), 1e-12});
  EnergyWindow w{1e300, -1e300, {}};
  for (const RunRecord* r : runs) {
    const auto [lo, hi] = finite_range(r->energy);
    if (lo > hi) continue;
    if (std::max(std::abs(lo - *start), std::abs(hi - *start)) > limit) {
      const double most = std::abs(hi - *start) >= std::abs(lo - *start) ? hi : lo;
      w.clipped.push_back(fmt::format("{} (reaches {:.3g} J)", r->backend, most));
    } else {
      w.low = std::min(w.low, lo), w.high = std::max(w.high, hi);
    }
  }
  if (w.clipped.empty() || w.low > w.high) return std::nullopt;
  const double pad = 0.08 * std::max(w.high - w.low, 1e-9 * std::max(1.0, std::abs(*start)));
  w.low -= pad, w.high += pad;
  return w;
}

}  // namespace

std::string energy_plot(const CaseResults& results, FileBatch& batch, const std::string& name) {
  const Scene& scene = *results.scene;
  const auto runs = report_runs(results);
  std::string data, plot;
  int block = 0;
  for (std::size_t i = 0; i < runs.size(); ++i) {
    // Each run's energy at every sample, measured where the run was (run_summary.hpp).
    const RunRecord& run = *runs[i];
    const std::string rows = series_rows(run.trajectory.times, run.energy);
    if (rows.empty()) continue;
    data += "# " + run.backend + "\n" + rows + "\n\n";
    plot += (plot.empty() ? "plot " : ", \\\n     ") + series_line(i, block++, run.backend);
  }
  if (plot.empty()) return "no run has a finite energy to draw";
  // A run far off the others' scale is cut at the window's edge; the title's next lines say
  // which, and how far each goes, wrapped to the width of the plot (the title is centred
  // over it: a line wider than the plot ran off the picture's left edge).
  std::vector<std::string> title = {scene.name + ": energy at report_dt"};
  std::string window;
  if (const auto w = energy_window(runs)) {
    window = fmt::format("set yrange [{:.9g}:{:.9g}]\n", w->low, w->high);
    for (const std::string& line :
         wrapped_items("off this scale, cut at its edge:", w->clipped, 0.7 * kPlotWidth, 12.0))
      title.push_back(line);
  }
  const std::string parts = scene.springs.empty() ? "kinetic + rotational + gravitational"
                                                  : "kinetic + rotational + gravitational + spring";
  const std::string script = fmt::format(
      "set grid\nset key outside right top\nset xlabel \"t (s)\"\n"
      "set ylabel {}\nset title {}\n{}{}\n",
      quote("total energy (J): " + parts), quote_lines(title), window, plot);
  return draw(script, data, batch, name);
}

}  // namespace bb
