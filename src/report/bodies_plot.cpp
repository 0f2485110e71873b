#include "report/bodies_plot.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <utility>

#include "report/backend_style.hpp"
#include "report/body_panels.hpp"
#include "report/gnuplot.hpp"
#include "report/off_scale.hpp"
#include "report/plot_layout.hpp"
#include "run/drawn_bodies.hpp"
#include "run/run_summary.hpp"

namespace bb {

namespace {

/// How far the guide moves the body at `slot` along each axis (max - min).
Vec3 motion_range(const Trajectory& guide, std::size_t slot) {
  Vec3 lo = Vec3::Constant(1e300), hi = Vec3::Constant(-1e300);
  for (const State& s : guide.states)
    if (slot < s.size() && s[slot].position.allFinite())
      lo = lo.cwiseMin(s[slot].position), hi = hi.cwiseMax(s[slot].position);
  return (hi - lo).cwiseMax(0.0);
}

/// The bodies the trajectory plot shows, as slots of the kept states: those that move,
/// ranked by how far the guide moves them plus how far the runs part from the guide, at
/// most kPlottedBodies, in the scene's order. A fixed or anchored body never gets a panel.
std::vector<std::size_t> plotted_slots(const Scene& scene, const std::vector<int>& drawn,
                                       const std::vector<const RunRecord*>& runs,
                                       const Trajectory& guide) {
  std::vector<std::pair<double, std::size_t>> ranked;
  for (std::size_t k = 0; k < drawn.size(); ++k) {
    if (scene.bodies[drawn[k]].fixed) continue;
    double apart = 0.0;
    for (const RunRecord* r : runs)
      for (std::size_t j = 0; j < r->trajectory.states.size() && j < guide.states.size(); ++j)
        if (k < r->trajectory.states[j].size()) {
          const double d =
              (r->trajectory.states[j][k].position - guide.states[j][k].position).norm();
          if (std::isfinite(d)) apart = std::max(apart, d);
        }
    const double score = motion_range(guide, k).maxCoeff() + apart;
    if (score > 0.0) ranked.push_back({score, k});
  }
  std::stable_sort(ranked.begin(), ranked.end(),
                   [](const auto& a, const auto& b) { return a.first > b.first; });
  std::vector<std::size_t> out;
  for (std::size_t i = 0; i < ranked.size() && i < kPlottedBodies; ++i)
    out.push_back(ranked[i].second);
  std::sort(out.begin(), out.end());
  return out;
}

/// The guide's last finite value of `pick` for the body at `slot`, if any.
template <typename Pick>
std::optional<std::pair<double, double>> last_point(const Trajectory& guide, std::size_t slot,
                                                    Pick pick) {
  for (std::size_t j = guide.states.size(); j-- > 0;)
    if (slot < guide.states[j].size()) {
      const auto [x, y] = pick(guide.times[j], guide.states[j][slot]);
      if (std::isfinite(x) && std::isfinite(y)) return std::pair{x, y};
    }
  return std::nullopt;
}

/// The guide's first finite value of `pick` for the body at `slot`, if any.
template <typename Pick>
std::optional<std::pair<double, double>> first_point(const Trajectory& guide, std::size_t slot,
                                                     Pick pick) {
  for (std::size_t j = 0; j < guide.states.size(); ++j)
    if (slot < guide.states[j].size()) {
      const auto [x, y] = pick(guide.times[j], guide.states[j][slot]);
      if (std::isfinite(x) && std::isfinite(y)) return std::pair{x, y};
    }
  return std::nullopt;
}

/// One run's series on one panel: per body of the group, its (across, value) points.
struct PanelRun {
  std::size_t run = 0;
  std::vector<std::vector<double>> across, value;
};

/// How far off the scale a cut run goes: the farthest value, and on which axis.
struct OffScale {
  double beyond = 0.0, value = 0.0;
  std::string axis;
};

}  // namespace

/// One panel per group of bodies (body_panels.hpp), every backend over the reference. With
/// `speed`, each body's speed against time; else its path y against x where the group moves
/// both ways in the plane, or the coordinate that moves most against time. Bodies sharing a
/// panel are named at the end of the reference's curve. A run far off the reference's scale
/// is cut at the axis and named above the panels; the legend has a band of its own.
std::string bodies_plot(const CaseResults& results, FileBatch& batch, const std::string& name,
                        bool speed) {
  const Scene& scene = *results.scene;
  const auto runs = report_runs(results);
  // The reference decides what is drawn; without one, the first run that has states.
  const Trajectory* guide = &results.reference_run.trajectory;
  for (const RunRecord* r : runs)
    if (guide->states.empty()) guide = &r->trajectory;
  const std::vector<int> drawn = drawn_bodies(scene);
  const auto panels_of = body_panels(scene, drawn, plotted_slots(scene, drawn, runs, *guide));
  std::string data, script;
  std::vector<LegendEntry> legend;
  std::map<std::size_t, OffScale> off;  // by run, the farthest over the panels
  int block = 0, panels = 0;
  for (const std::vector<std::size_t>& group : panels_of) {
    Vec3 range = Vec3::Zero();
    bool path = !speed && scene.dims == 2;
    for (std::size_t k : group) {
      const Vec3 r = motion_range(*guide, k);
      range = range.cwiseMax(r);
      path = path && std::min(r.x(), r.y()) > 0.05 * r.maxCoeff();
    }
    Eigen::Index axis = 1;
    range.maxCoeff(&axis);
    // What the panel plots of a body's state at time t: (across, value).
    const auto pick = [&](double t, const BodyState& b) {
      if (speed) return std::pair{t, b.velocity.norm()};
      return path ? std::pair{b.position.x(), b.position.y()} : std::pair{t, b.position[axis]};
    };
    // Every run's points, and the guide's extent on each axis.
    std::vector<PanelRun> series;
    for (std::size_t i = 0; i < runs.size(); ++i) {
      const Trajectory& t = runs[i]->trajectory;
      // A run without states (a reference with no answer) draws nothing.
      if (t.states.empty()) continue;
      PanelRun run{i, {}, {}};
      for (std::size_t k : group) {
        run.across.emplace_back();
        run.value.emplace_back();
        for (std::size_t j = 0; j < t.states.size(); ++j) {
          const auto [x, y] = pick(t.times[j], t.states[j][k]);
          run.across.back().push_back(x);
          run.value.back().push_back(y);
        }
      }
      series.push_back(std::move(run));
    }
    Extent guide_x, guide_y;
    for (std::size_t k : group)
      for (std::size_t j = 0; j < guide->states.size(); ++j) {
        const auto [x, y] = pick(guide->times[j], guide->states[j][k]);
        guide_x.add(x), guide_y.add(y);
      }
    // How far each run leaves the guide's extent (across only on a path), against the
    // panel's scale.
    std::vector<double> reach;
    for (const PanelRun& run : series) {
      double most = 0.0;
      for (std::size_t g = 0; g < group.size(); ++g)
        for (std::size_t j = 0; j < run.value[g].size(); ++j) {
          most = std::max(most, guide_y.beyond(run.value[g][j]));
          if (path) most = std::max(most, guide_x.beyond(run.across[g][j]));
        }
      reach.push_back(most);
    }
    const double span = path ? std::max(guide_x.span(), guide_y.span()) : guide_y.span();
    const double tiny = 1e-9 * (1.0 + std::max(std::abs(guide_y.lo), std::abs(guide_y.hi)));
    const double limit = off_scale_limit(reach, span, tiny);
    Extent window_x = guide_x, window_y = guide_y;
    bool cut = false;
    std::string plot, labels, names;
    std::vector<LegendEntry> titled;
    for (std::size_t s = 0; s < series.size(); ++s) {
      const PanelRun& run = series[s];
      const std::size_t i = run.run;
      const bool off_scale = guide_y.empty() ? false : reach[s] > limit;
      if (off_scale) {
        // Named with the value farthest off the guide's extent.
        cut = true;
        OffScale& o = off[i];
        for (std::size_t g = 0; g < group.size(); ++g)
          for (std::size_t j = 0; j < run.value[g].size(); ++j) {
            const auto note = [&](double v, const Extent& e, const std::string& on) {
              if (e.beyond(v) > o.beyond) o = {e.beyond(v), v, on};
            };
            note(run.value[g][j], guide_y,
                 speed  ? "speed"
                 : path ? "y"
                        : std::string(1, "xyz"[axis]));
            if (path) note(run.across[g][j], guide_x, "x");
          }
      }
      for (std::size_t g = 0; g < group.size(); ++g) {
        if (!off_scale)
          for (std::size_t j = 0; j < run.value[g].size(); ++j)
            window_x.add(run.across[g][j]), window_y.add(run.value[g][j]);
        const std::string rows = series_rows(run.across[g], run.value[g]);
        if (rows.empty()) continue;
        data += "# " + runs[i]->backend + "\n" + rows + "\n\n";
        plot += (plot.empty() ? "plot " : ", \\\n     ") +
                series_line(i, block++, runs[i]->backend, g == 0);
        if (g == 0) titled.push_back({runs[i]->backend, series_style(i, runs[i]->backend)});
      }
    }
    for (std::size_t g = 0; g < group.size(); ++g) {
      const std::size_t k = group[g];
      const std::string& who = scene.bodies[drawn[k]].name;
      names += (names.empty() ? "" : ", ") + who;
      // Each body of a shared panel is named where the reference's curve ends, on the side
      // of the panel that leaves the text inside it.
      if (const auto end = last_point(*guide, k, pick); end && group.size() > 1) {
        // The curve ends right of where it began: the name reads leftwards from its end.
        const auto begin = first_point(*guide, k, pick);
        const bool right_half = !begin || end->first > begin->first;
        labels += fmt::format("set label {} at {:.9g},{:.9g} {} offset {},0.8 front\n", quote(who),
                              end->first, end->second, right_half ? "right" : "left",
                              right_half ? -0.5 : 0.5);
      }
    }
    // A group no run has a finite value for leaves its panel empty.
    if (plot.empty()) continue;
    // The legend is the first panel's.
    if (++panels == 1) legend = titled;
    const std::string y_label = speed  ? names + " speed (m/s)"
                                : path ? names + " y (m)"
                                       : names + " " + "xyz"[axis] + " (m)";
    const std::string x_label = path ? names + " x (m)" : "t (s)";
    // The axes of a panel with a run cut: the guide's and the kept runs' values, padded.
    std::string window = "set autoscale xy\n";
    const auto padded = [](const Extent& e) {
      const double pad = 0.05 * std::max(e.span(), 1e-9 * (1.0 + std::abs(e.hi)));
      return fmt::format("[{:.9g}:{:.9g}]", e.lo - pad, e.hi + pad);
    };
    if (cut) {
      window += "set yrange " + padded(window_y) + "\n";
      if (path) window += "set xrange " + padded(window_x) + "\n";
    }
    script += fmt::format("unset label\n{}{}set xlabel {}\nset ylabel {}\n{}\n", labels, window,
                          quote(x_label), quote(y_label), plot);
  }
  if (panels == 0)
    return "no run has a finite " + std::string(speed ? "velocity" : "position") + " to draw";
  // The runs cut at an axis, in the order of the runs, each with the farthest it goes.
  std::vector<std::string> cut_runs;
  for (const auto& [i, o] : off)
    cut_runs.push_back(fmt::format("{} (reaches {}{:.3g} {})", runs[i]->backend,
                                   o.axis == "speed" ? "" : o.axis + " = ", o.value,
                                   speed ? "m/s" : "m"));
  std::vector<std::string> title = {
      scene.name + (speed ? ": speed at report_dt" : ": where the moving bodies go, at report_dt")};
  if (!cut_runs.empty())
    for (const std::string& line :
         wrapped_items("off this scale, cut at its edge:", cut_runs, kPlotWidth - 80, 12.0))
      title.push_back(line);
  const int title_extra = 16 * static_cast<int>(title.size() - 1);
  // One legend, in its band right of the panels; every panel keeps the same right margin to
  // line up.
  const LegendBand band = legend_band(legend, 40 + title_extra);
  const int height = std::max(80 + 280 * panels + title_extra, band.height + 40);
  const std::string layout = fmt::format(
      "set multiplot layout {},1 title {}\nset grid\nset clip two\nunset key\n"
      "set rmargin at screen {:.4f}\n",
      panels, quote_lines(title), band.panels_right);
  return draw(layout + script + band.plot(height) + "unset multiplot\n", data, batch, name, height);
}

}  // namespace bb
