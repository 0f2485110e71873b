#include "report/sweep_page.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "report/format.hpp"
#include "report/gnuplot.hpp"
#include "report/markdown_text.hpp"
#include "report/off_scale.hpp"
#include "report/table.hpp"
#include "study/backend_names.hpp"

namespace bb {

namespace {

/// Most values for which the page lists every one.
constexpr std::size_t kMaxListedValues = 12;

/// The backends of the sweep, the reference first, in the order the points list them.
std::vector<std::string> sweep_backends(const SweepResults& sweep) {
  std::vector<std::string> out;
  for (const SweepPoint& p : sweep.points)
    for (const RunRecord& run : p.runs)
      if (std::find(out.begin(), out.end(), run.backend) == out.end()) out.push_back(run.backend);
  return out;
}

const RunRecord* run_of(const SweepPoint& point, const std::string& backend) {
  for (const RunRecord& run : point.runs)
    if (run.backend == backend) return &run;
  return nullptr;
}

/// The quantities the sweep shows: the case's observables, then position_max.
std::vector<std::string> sweep_quantities(const Scene& scene) {
  std::vector<std::string> out;
  for (const Observe& o : scene.observes) out.push_back(o.name);
  out.push_back("position_max");
  return out;
}

/// `backend`'s value of `quantity` at each point (absent where it has none).
std::vector<std::optional<double>> series_of(const SweepResults& sweep, const std::string& backend,
                                             const std::string& quantity) {
  std::vector<std::optional<double>> out;
  for (const SweepPoint& p : sweep.points) {
    const RunRecord* run = run_of(p, backend);
    out.push_back(run ? run_quantity(*run, quantity) : std::nullopt);
  }
  return out;
}

/// The points where both the parameter and the value exist, for drawing.
void add_series(TwoColumnPlot& plot, bool right, std::size_t i, const std::string& backend,
                const SweepResults& sweep, const std::vector<std::optional<double>>& values) {
  std::vector<double> x, y;
  for (std::size_t k = 0; k < values.size(); ++k)
    if (values[k] && std::isfinite(*values[k]))
      x.push_back(sweep.points[k].value), y.push_back(*values[k]);
  plot.add(right, i, backend, x, y);
}

/// Largest |change| between neighbouring values where both exist.
std::optional<double> largest_step(const std::vector<std::optional<double>>& values) {
  std::optional<double> out;
  for (std::size_t k = 1; k < values.size(); ++k)
    if (values[k] && values[k - 1])
      out = std::max(out.value_or(0.0), std::abs(*values[k] - *values[k - 1]));
  return out;
}

/// Which way a result goes as the parameter grows, where it has values: "rises", "falls",
/// "flat", or "up and down" (a result that should follow the parameter and does not).
std::string trend(const std::vector<std::optional<double>>& values) {
  bool up = false, down = false;
  std::optional<double> last;
  for (const auto& v : values) {
    if (!v) continue;
    if (last && *v > *last) up = true;
    if (last && *v < *last) down = true;
    last = v;
  }
  if (!last) return "-";
  return up && down ? "up and down" : up ? "rises" : down ? "falls" : "flat";
}

std::string range_text(const std::vector<std::optional<double>>& values) {
  std::optional<double> lo, hi;
  for (const auto& v : values)
    if (v) lo = std::min(lo.value_or(*v), *v), hi = std::max(hi.value_or(*v), *v);
  if (!lo) return "-";
  return format_value(lo) + " to " + format_value(hi);
}

/// A cell for one backend at one point: its value, else its status or why it has none.
std::string cell(const SweepPoint& point, const std::string& backend, const std::string& quantity) {
  const RunRecord* run = run_of(point, backend);
  if (run == nullptr) return "-";
  if (run->status != RunStatus::Ok) return status_name(run->status);
  if (const std::optional<double> v = run_quantity(*run, quantity)) return format_value(v);
  // An observable the run has no value for says why.
  for (const ObservableResult& o : run->observables)
    if (o.name == quantity && !o.measured.note.empty()) return o.measured.note;
  return "-";
}

std::string onset_section(const SweepResults& sweep, const Sweep& spec,
                          const std::vector<std::string>& backends) {
  Table t{{"backend", "first " + spec.parameter + " where " + spec.onset + " above " +
                          short_number(spec.onset_above)},
          {},
          {false, true}};
  for (const std::string& b : backends) {
    std::string first = "never in the sweep";
    for (const SweepPoint& p : sweep.points) {
      const RunRecord* run = run_of(p, b);
      const std::optional<double> v = run ? run_quantity(*run, spec.onset) : std::nullopt;
      if (v && *v > spec.onset_above) {
        first = short_number(p.value);
        break;
      }
    }
    t.rows.push_back({b, first});
  }
  return fmt::format(
      "\n### Where it starts\n\nThe first swept value at which `{}` exceeds {}: where the "
      "reference's and a backend's differ, the backend moves the threshold.\n\n{}",
      markdown_text(spec.onset), short_number(spec.onset_above), render_markdown(t));
}

using Series = std::vector<std::optional<double>>;

/// A panel's backends off the reference's scale (off_scale.hpp), each named with the value
/// farthest off, and the window the others span; no window when none is cut.
struct PanelCut {
  std::vector<std::string> named;
  TwoColumnPlot::Window window;
};

PanelCut cut_of(const std::vector<std::string>& backends, const std::vector<Series>& series) {
  const auto guide_at = std::find(backends.begin(), backends.end(), kReferenceName);
  if (guide_at == backends.end()) return {};
  Extent guide;
  for (const auto& v : series[guide_at - backends.begin()])
    if (v) guide.add(*v);
  if (guide.empty()) return {};
  std::vector<double> reach;
  for (const Series& s : series) {
    double most = 0.0;
    for (const auto& v : s)
      if (v) most = std::max(most, guide.beyond(*v));
    reach.push_back(most);
  }
  const double tiny = 1e-9 * (1.0 + std::max(std::abs(guide.lo), std::abs(guide.hi)));
  const double limit = off_scale_limit(reach, guide.span(), tiny);
  PanelCut out;
  Extent kept;
  for (std::size_t i = 0; i < series.size(); ++i) {
    double farthest = 0.0, by = -1.0;
    for (const auto& v : series[i])
      if (v && guide.beyond(*v) > by) farthest = *v, by = guide.beyond(*v);
    if (reach[i] > limit)
      out.named.push_back(fmt::format("{} (reaches {:.3g})", backends[i], farthest));
    else
      for (const auto& v : series[i])
        if (v) kept.add(*v);
  }
  if (out.named.empty()) return out;
  const double pad = 0.05 * std::max(kept.span(), tiny);
  out.window = std::pair{kept.lo - pad, kept.hi + pad};
  return out;
}

/// A panel's name, and the backends cut at its edge.
std::string panel_label(const std::string& name, const PanelCut& cut) {
  if (cut.named.empty()) return name;
  std::string out = name + "; off this scale, cut at its edge:";
  for (std::size_t i = 0; i < cut.named.size(); ++i) out += (i ? ", " : " ") + cut.named[i];
  return out;
}

/// Adds a row of `values` (left) and `off` (right), one series per backend, each panel
/// scaled to the backends on the reference's scale.
void add_row(TwoColumnPlot& plot, const SweepResults& sweep,
             const std::vector<std::string>& backends, const std::vector<Series>& values,
             const std::vector<Series>& off, const std::string& left, const std::string& right) {
  for (std::size_t i = 0; i < backends.size(); ++i) {
    add_series(plot, false, i, backends[i], sweep, values[i]);
    add_series(plot, true, i, backends[i], sweep, off[i]);
  }
  const PanelCut left_cut = cut_of(backends, values), right_cut = cut_of(backends, off);
  plot.end_row(panel_label(left, left_cut), panel_label(right, right_cut), left_cut.window,
               right_cut.window);
}

}  // namespace

std::string sweep_plot(const CaseResults& results, FileBatch& batch, const std::string& name) {
  if (!results.sweep) return "the case has no sweep";
  if (!results.sweep->second_parameter.empty()) return "a map is drawn by map_picture.hpp";
  const SweepResults& sweep = *results.sweep;
  const Scene& scene = *results.scene;
  const std::vector<std::string> backends = sweep_backends(sweep);
  TwoColumnPlot plot(scene.name + ": the sweep of " + sweep.parameter + " at report_dt",
                     sweep.parameter);
  // Every panel spans the whole sweep: a difference panel has no point where the reference
  // has no answer, and started at another value than the value panel beside it.
  Extent swept;
  for (const SweepPoint& p : sweep.points) swept.add(p.value);
  if (swept.span() > 0.0) plot.set_x_range(swept.lo, swept.hi);
  for (const Observe& o : scene.observes) {
    const Series reference = series_of(sweep, kReferenceName, o.name);
    std::vector<Series> values, off;
    for (const std::string& b : backends) {
      values.push_back(series_of(sweep, b, o.name));
      off.emplace_back(reference.size());
      for (std::size_t k = 0; k < reference.size(); ++k)
        if (values.back()[k] && reference[k]) off.back()[k] = *values.back()[k] - *reference[k];
    }
    add_row(plot, sweep, backends, values, off, o.name, o.name + " minus the reference's");
  }
  std::vector<Series> position, energy;
  for (const std::string& b : backends) {
    position.push_back(series_of(sweep, b, "position_max"));
    energy.push_back(series_of(sweep, b, "energy_max"));
  }
  add_row(plot, sweep, backends, position, energy, "position_max (m)", "energy_max");
  return plot.draw_into(batch, name);
}

namespace {

/// Predictability: how far a result moves from one value to the next, per backend.
std::string predictability_section(const SweepResults& sweep,
                                   const std::vector<std::string>& backends,
                                   const std::vector<std::string>& quantities) {
  Table t{{"backend"}, {}, {false}};
  for (const std::string& q : quantities) {
    t.headers.push_back(q + ": trend");
    t.headers.push_back(q + ": range");
    t.headers.push_back(q + ": largest step");
    t.right_aligned.push_back(false);
    t.right_aligned.push_back(true);
    t.right_aligned.push_back(true);
  }
  for (const std::string& b : backends) {
    std::vector<std::string> row{b};
    for (const std::string& q : quantities) {
      const auto values = series_of(sweep, b, q);
      row.push_back(trend(values));
      row.push_back(range_text(values));
      row.push_back(format_value(largest_step(values)));
    }
    t.rows.push_back(row);
  }
  return fmt::format(
      "\n### Predictability\n\nWhich way each result goes as the parameter grows (rises, falls, "
      "flat, or up and down), how far it moves over the sweep, "
      "and its largest change between neighbouring values: a small change of the parameter "
      "should give a small change of the result (Chung and Pollard 2016); a largest step well "
      "above the reference's is a jump.\n\n{}",
      render_markdown(t));
}

/// Every value of every quantity, one table per quantity.
std::string every_value_section(const SweepResults& sweep, const std::vector<std::string>& backends,
                                const std::vector<std::string>& quantities) {
  std::string out;
  out += "\n### Every value\n";
  for (const std::string& q : quantities) {
    Table v{{"backend"}, {}, {false}};
    for (const SweepPoint& p : sweep.points) {
      v.headers.push_back(sweep.parameter + " = " + short_number(p.value));
      v.right_aligned.push_back(true);
    }
    for (const std::string& b : backends) {
      std::vector<std::string> row{b};
      for (const SweepPoint& p : sweep.points) row.push_back(cell(p, b, q));
      v.rows.push_back(row);
    }
    out += fmt::format("\n`{}`:\n\n{}", markdown_text(q), render_markdown(v));
  }
  return out;
}

}  // namespace

std::string sweep_markdown(const CaseResults& results, const std::string& plot) {
  // A map's section is map_page.hpp's.
  if (!results.sweep || !results.scene->sweep || results.scene->second_sweep) return "";
  const SweepResults& sweep = *results.sweep;
  const Scene& scene = *results.scene;
  const Sweep& spec = *scene.sweep;
  const std::vector<std::string> backends = sweep_backends(sweep);
  std::string out = fmt::format("\n## Sweep of `{}`\n\n", markdown_text(sweep.parameter));
  if (!spec.published.empty())
    out += "**What the published study found.** " + markdown_text(spec.published) + "\n\n";
  const auto no_reference =
      std::count_if(sweep.points.begin(), sweep.points.end(), [](const SweepPoint& p) {
        const RunRecord* r = run_of(p, kReferenceName);
        return r == nullptr || r->status != RunStatus::Ok;
      });
  out += fmt::format(
      "The whole case run again at each of {} values of `{}` (from {} to {}), every backend at "
      "{}. Each value's errors are against the reference at that value{}.{}\n\n",
      sweep.points.size(), markdown_text(sweep.parameter), short_number(spec.values.front()),
      short_number(spec.values.back()),
      sweep.parameter == "dt" ? "that step" : "report_dt = " + format_dt(scene.report_dt) + " s",
      no_reference > 0 ? fmt::format(" (the reference has no answer at {} of them: there a "
                                     "backend has no errors, only its observables)",
                                     no_reference)
                       : "",
      sweep.parameter == "ground.normal"
          ? " `ground.normal` is the ground's tilt from level in degrees; the bodies on it "
            "are tilted with it."
          : "");
  if (!plot.empty())
    out +=
        "Left: each quantity against the parameter, the reference thick and black; right: "
        "its difference from the reference's at the same value (last row: the error "
        "metrics); a backend far off the reference's scale in a panel is cut at its edge and "
        "named above it.\n\n![sweep](" +
        plot + ")\n";
  if (!spec.onset.empty()) out += onset_section(sweep, spec, backends);

  const std::vector<std::string> quantities = sweep_quantities(scene);
  out += predictability_section(sweep, backends, quantities);
  if (sweep.points.size() <= kMaxListedValues)
    out += every_value_section(sweep, backends, quantities);
  return out;
}

}  // namespace bb
