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

/// What a panel plots of a body's state at time t, as (across, value): with `speed` its
/// speed against time, on a `path` its y against its x, else its coordinate along `axis`
/// against time.
struct PanelPick {
  bool speed = false, path = false;
  Eigen::Index axis = 1;
  std::pair<double, double> operator()(double t, const BodyState& b) const {
    if (speed) return std::pair{t, b.velocity.norm()};
    return path ? std::pair{b.position.x(), b.position.y()} : std::pair{t, b.position[axis]};
  }
  /// The name of the value's axis, as a cut run's reach is given.
  std::string value_axis() const {
    return speed ? "speed" : path ? "y" : std::string(1, "xyz"[axis]);
  }
};

/// The guide's first finite point of the body at `slot` (its last with `from_end`), if any.
std::optional<std::pair<double, double>> finite_point(const Trajectory& guide, std::size_t slot,
                                                      const PanelPick& pick, bool from_end) {
  const std::size_t n = guide.states.size();
  for (std::size_t step = 0; step < n; ++step) {
    const std::size_t j = from_end ? n - 1 - step : step;
    if (slot < guide.states[j].size()) {
      const auto [x, y] = pick(guide.times[j], guide.states[j][slot]);
      if (std::isfinite(x) && std::isfinite(y)) return std::pair{x, y};
    }
  }
  return std::nullopt;
}

/// The pick of a group's panel: its path where the group moves both ways in the plane (a
/// 2D scene, without `speed`), else the coordinate the guide moves most.
PanelPick panel_pick(const Scene& scene, const Trajectory& guide,
                     const std::vector<std::size_t>& group, bool speed) {
  PanelPick pick;
  pick.speed = speed;
  pick.path = !speed && scene.dims == 2;
  Vec3 range = Vec3::Zero();
  for (std::size_t k : group) {
    const Vec3 r = motion_range(guide, k);
    range = range.cwiseMax(r);
    pick.path = pick.path && std::min(r.x(), r.y()) > 0.05 * r.maxCoeff();
  }
  range.maxCoeff(&pick.axis);
  return pick;
}

/// Every run's points on the panel of `group`; a run without states (a reference with no
/// answer) draws nothing.
std::vector<PanelRun> panel_series(const std::vector<const RunRecord*>& runs,
                                   const std::vector<std::size_t>& group, const PanelPick& pick) {
  std::vector<PanelRun> series;
  for (std::size_t i = 0; i < runs.size(); ++i) {
    const Trajectory& t = runs[i]->trajectory;
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
  return series;
}

/// The extent of a panel's points on each of its axes.
struct PanelExtent {
  Extent x, y;
};

/// The guide's extent on the panel of `group`.
PanelExtent guide_extent(const Trajectory& guide, const std::vector<std::size_t>& group,
                         const PanelPick& pick) {
  PanelExtent out;
  for (std::size_t k : group)
    for (std::size_t j = 0; j < guide.states.size(); ++j) {
      const auto [x, y] = pick(guide.times[j], guide.states[j][k]);
      out.x.add(x), out.y.add(y);
    }
  return out;
}

/// Per series, whether it is off the panel's scale: how far it leaves the guide's extent
/// (across only on a path), against the guide's span and the other runs' reach.
std::vector<bool> off_scale_series(const std::vector<PanelRun>& series, const PanelExtent& guide,
                                   bool path) {
  std::vector<double> reach;
  for (const PanelRun& run : series) {
    double most = 0.0;
    for (std::size_t g = 0; g < run.value.size(); ++g)
      for (std::size_t j = 0; j < run.value[g].size(); ++j) {
        most = std::max(most, guide.y.beyond(run.value[g][j]));
        if (path) most = std::max(most, guide.x.beyond(run.across[g][j]));
      }
    reach.push_back(most);
  }
  const double span = path ? std::max(guide.x.span(), guide.y.span()) : guide.y.span();
  const double tiny = 1e-9 * (1.0 + std::max(std::abs(guide.y.lo), std::abs(guide.y.hi)));
  const double limit = off_scale_limit(reach, span, tiny);
  std::vector<bool> out;
  for (double r : reach) out.push_back(guide.y.empty() ? false : r > limit);
  return out;
}

/// Notes in `o` the value of a cut run farthest off the guide's extent, and its axis.
void note_farthest(const PanelRun& run, const PanelExtent& guide, const PanelPick& pick,
                   OffScale& o) {
  const auto note = [&](double v, const Extent& e, const std::string& on) {
    if (e.beyond(v) > o.beyond) o = {e.beyond(v), v, on};
  };
  for (std::size_t g = 0; g < run.value.size(); ++g)
    for (std::size_t j = 0; j < run.value[g].size(); ++j) {
      note(run.value[g][j], guide.y, pick.value_axis());
      if (pick.path) note(run.across[g][j], guide.x, "x");
    }
}

/// A panel's series drawn: its plot command, the legend entries its runs bring, whether a
/// run was cut, and the extent of the guide and the runs kept on the scale.
struct DrawnSeries {
  std::string plot;
  std::vector<LegendEntry> titled;
  bool cut = false;
  PanelExtent window;
};

/// Every series of a panel: its rows into `data` as gnuplot's blocks, numbered on from
/// `block`, and its line in the plot command.
DrawnSeries draw_series(const std::vector<const RunRecord*>& runs,
                        const std::vector<PanelRun>& series, const std::vector<bool>& off_scale,
                        const PanelExtent& guide, std::string& data, int& block) {
  DrawnSeries out;
  out.window = guide;
  for (std::size_t s = 0; s < series.size(); ++s) {
    const PanelRun& run = series[s];
    const std::size_t i = run.run;
    out.cut = out.cut || off_scale[s];
    for (std::size_t g = 0; g < run.value.size(); ++g) {
      if (!off_scale[s])
        for (std::size_t j = 0; j < run.value[g].size(); ++j)
          out.window.x.add(run.across[g][j]), out.window.y.add(run.value[g][j]);
      const std::string rows = series_rows(run.across[g], run.value[g]);
      if (rows.empty()) continue;
      data += "# " + runs[i]->backend + "\n" + rows + "\n\n";
      out.plot += (out.plot.empty() ? "plot " : ", \\\n     ") +
                  series_line(i, block++, runs[i]->backend, g == 0);
      if (g == 0) out.titled.push_back({runs[i]->backend, series_style(i, runs[i]->backend)});
    }
  }
  return out;
}

/// A panel's bodies by name, and the gnuplot labels that name each where the reference's
/// curve ends when they share the panel.
struct BodyNames {
  std::string names, labels;
};

BodyNames body_names(const Scene& scene, const std::vector<int>& drawn,
                     const std::vector<std::size_t>& group, const Trajectory& guide,
                     const PanelPick& pick) {
  BodyNames out;
  for (std::size_t k : group) {
    const std::string& who = scene.bodies[drawn[k]].name;
    out.names += (out.names.empty() ? "" : ", ") + who;
    // Each body of a shared panel is named where the reference's curve ends, on the side
    // of the panel that leaves the text inside it.
    if (const auto end = finite_point(guide, k, pick, true); end && group.size() > 1) {
      // The curve ends right of where it began: the name reads leftwards from its end.
      const auto begin = finite_point(guide, k, pick, false);
      const bool right_half = !begin || end->first > begin->first;
      out.labels += fmt::format("set label {} at {:.9g},{:.9g} {} offset {},0.8 front\n",
                                quote(who), end->first, end->second, right_half ? "right" : "left",
                                right_half ? -0.5 : 0.5);
    }
  }
  return out;
}

/// A panel's gnuplot commands: its labels, its axes (where a run is cut, the guide's and the
/// kept runs' values, padded), its axis titles and its plot.
std::string panel_script(const PanelPick& pick, const BodyNames& bodies, const DrawnSeries& drawn) {
  const std::string& names = bodies.names;
  const std::string y_label = pick.speed  ? names + " speed (m/s)"
                              : pick.path ? names + " y (m)"
                                          : names + " " + "xyz"[pick.axis] + " (m)";
  const std::string x_label = pick.path ? names + " x (m)" : "t (s)";
  std::string window = "set autoscale xy\n";
  const auto padded = [](const Extent& e) {
    const double pad = 0.05 * std::max(e.span(), 1e-9 * (1.0 + std::abs(e.hi)));
    return fmt::format("[{:.9g}:{:.9g}]", e.lo - pad, e.hi + pad);
  };
  if (drawn.cut) {
    window += "set yrange " + padded(drawn.window.y) + "\n";
    if (pick.path) window += "set xrange " + padded(drawn.window.x) + "\n";
  }
  return fmt::format("unset label\n{}{}set xlabel {}\nset ylabel {}\n{}\n", bodies.labels, window,
                     quote(x_label), quote(y_label), drawn.plot);
}

/// The plot's title: the case and what it shows, then the runs cut at an axis, in the order
/// of the runs, each with the farthest it goes.
std::vector<std::string> plot_title(const Scene& scene, const std::vector<const RunRecord*>& runs,
                                    const std::map<std::size_t, OffScale>& off, bool speed) {
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
  return title;
}

/// The trajectory that decides what is drawn: the reference's, or without one the first
/// run's that has states.
const Trajectory& guide_of(const CaseResults& results, const std::vector<const RunRecord*>& runs) {
  const Trajectory* guide = &results.reference_run.trajectory;
  for (const RunRecord* r : runs)
    if (guide->states.empty()) guide = &r->trajectory;
  return *guide;
}

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
  const Trajectory& guide = guide_of(results, runs);
  const std::vector<int> drawn = drawn_bodies(scene);
  const auto panels_of = body_panels(scene, drawn, plotted_slots(scene, drawn, runs, guide));
  std::string data, script;
  std::vector<LegendEntry> legend;
  std::map<std::size_t, OffScale> off;  // by run, the farthest over the panels
  int block = 0, panels = 0;
  for (const std::vector<std::size_t>& group : panels_of) {
    const PanelPick pick = panel_pick(scene, guide, group, speed);
    const std::vector<PanelRun> series = panel_series(runs, group, pick);
    const PanelExtent extent = guide_extent(guide, group, pick);
    const std::vector<bool> off_scale = off_scale_series(series, extent, pick.path);
    for (std::size_t s = 0; s < series.size(); ++s)
      if (off_scale[s]) note_farthest(series[s], extent, pick, off[series[s].run]);
    const DrawnSeries drawn_series = draw_series(runs, series, off_scale, extent, data, block);
    // A group no run has a finite value for leaves its panel empty.
    if (drawn_series.plot.empty()) continue;
    // The legend is the first panel's.
    if (++panels == 1) legend = drawn_series.titled;
    script += panel_script(pick, body_names(scene, drawn, group, guide, pick), drawn_series);
  }
  if (panels == 0)
    return "no run has a finite " + std::string(speed ? "velocity" : "position") + " to draw";
  const std::vector<std::string> title = plot_title(scene, runs, off, speed);
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
