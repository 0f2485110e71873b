#include "report/map_picture.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "model/text.hpp"
#include "report/map_cells.hpp"
#include "report/map_colour.hpp"
#include "report/xml_text.hpp"

namespace bb {

namespace {

/// The panel's frame around its cells, in px.
constexpr double kLeft = 64.0, kTop = 34.0, kBottom = 44.0, kRight = 12.0;
/// The cells of a panel fill at most this many px each way, each at most kLargestCell.
constexpr double kCellsExtent = 216.0, kLargestCell = 27.0;
/// Most panels side by side in the small multiples.
constexpr std::size_t kPanelsPerRow = 4;
/// The legend's height under the small multiples.
constexpr double kLegendHeight = 64.0;

std::string num(double v) {
  return fmt::format("{:.2f}", v);
}

const char* outcome_fill(MapOutcome outcome) {
  switch (outcome) {
    case MapOutcome::Ok:
      return "#74c476";
    case MapOutcome::PastOnset:
      return "#fd8d3c";
    case MapOutcome::Diverged:
      return "#cb181d";
    case MapOutcome::Unsupported:
      return "#bdbdbd";
    case MapOutcome::Failed:
      return "#6a51a3";
    case MapOutcome::Absent:
      break;
  }
  return "#ffffff";
}

double cell_size(const Scene& scene) {
  const double most =
      static_cast<double>(std::max(scene.sweep->values.size(), scene.second_sweep->values.size()));
  return std::min(kLargestCell, std::floor(kCellsExtent / most));
}

double panel_width(const Scene& scene) {
  return kLeft + cell_size(scene) * static_cast<double>(scene.second_sweep->values.size()) + kRight;
}

double panel_height(const Scene& scene) {
  return kTop + cell_size(scene) * static_cast<double>(scene.sweep->values.size()) + kBottom;
}

const RunRecord* run_at(const SweepPoint& point, const std::string& backend) {
  for (const RunRecord& run : point.runs)
    if (run.backend == backend) return &run;
  return nullptr;
}

/// A value as an axis labels it: a step as a frame rate's ("1/60"), else short.
std::string axis_label(const MapAxis& axis, std::size_t k) {
  return axis.parameter == "dt" ? format_dt(axis.values[k]) : short_number(axis.values[k]);
}

/// Every how many cells an axis labels a value, so that its widest label (about 6.5 px a
/// character at the labels' size, and a gap) never overlaps the next.
std::size_t label_step(const MapAxis& axis, double cell, bool across) {
  std::size_t widest = 0;
  for (std::size_t k = 0; k < axis.values.size(); ++k)
    widest = std::max(widest, axis_label(axis, k).size());
  const double label_px = across ? 6.5 * static_cast<double>(widest) + 8.0 : 14.0;
  return std::max<std::size_t>(1, static_cast<std::size_t>(std::ceil(label_px / cell)));
}

/// The axes' values and names around a panel's cells at (`x`, `y`).
std::string axes(const Scene& scene, double x, double y) {
  const MapAxis rows = map_rows(scene), columns = map_columns(scene);
  const double cell = cell_size(scene);
  const double rows_px = cell * static_cast<double>(rows.values.size());
  std::string out;
  for (std::size_t k = 0; k < rows.values.size(); k += label_step(rows, cell, false))
    out += fmt::format("<text x=\"{}\" y=\"{}\" text-anchor=\"end\" font-size=\"10\">{}</text>\n",
                       num(x - 3.0), num(y + rows_px - (static_cast<double>(k) + 0.5) * cell + 3.0),
                       axis_label(rows, k));
  for (std::size_t k = 0; k < columns.values.size(); k += label_step(columns, cell, true))
    out +=
        fmt::format("<text x=\"{}\" y=\"{}\" text-anchor=\"middle\" font-size=\"10\">{}</text>\n",
                    num(x + (static_cast<double>(k) + 0.5) * cell), num(y + rows_px + 13.0),
                    axis_label(columns, k));
  out += fmt::format("<text x=\"{}\" y=\"{}\" text-anchor=\"middle\">{}</text>\n",
                     num(x + cell * static_cast<double>(columns.values.size()) / 2.0),
                     num(y + rows_px + 30.0), escape_xml(columns.parameter));
  out += fmt::format(
      "<text transform=\"translate({},{}) rotate(-90)\" text-anchor=\"middle\">{}</text>\n",
      num(x - 48.0), num(y + rows_px / 2.0), escape_xml(rows.parameter));
  return out;
}

/// The drawn mark's SVG on the cell at (`x`, `y`), `cell` px wide: a cross, a ring or "?".
std::string mark_svg(MapMark mark, double x, double y, double cell) {
  const double m = cell * 0.22, cx = x + cell / 2.0, cy = y + cell / 2.0;
  switch (mark) {
    case MapMark::Cross:
      return fmt::format(
          "<path d=\"M{0},{1} L{2},{3} M{0},{3} L{2},{1}\" stroke=\"#000000\" "
          "stroke-width=\"2\"/>\n",
          num(x + m), num(y + m), num(x + cell - m), num(y + cell - m));
    case MapMark::Ring:
      return fmt::format(
          "<circle cx=\"{}\" cy=\"{}\" r=\"{}\" fill=\"none\" stroke=\"#000000\" "
          "stroke-width=\"1.5\"/>\n",
          num(cx), num(cy), num(cell / 2.0 - m));
    case MapMark::Question:
      return fmt::format(
          "<text x=\"{}\" y=\"{}\" text-anchor=\"middle\" font-size=\"{}\">?</text>\n", num(cx),
          num(cy + cell * 0.2), num(cell * 0.6));
    case MapMark::None:
      break;
  }
  return "";
}

/// A panel's title over its cells (from `left`); a longer one starts at the panel's edge
/// (`x`), and one longer still is condensed to the panel's width rather than run into the next.
std::string panel_title(const std::string& heading, double x, double left, double y, double width) {
  const double wide = kMapBoldCharWidth * static_cast<double>(heading.size());
  const double over_cells = x + width - left, over_panel = width - 16.0;
  const double start = wide <= over_cells ? left : x + 8.0;
  const std::string squeeze =
      wide <= over_cells || wide <= over_panel
          ? ""
          : fmt::format(" textLength=\"{}\" lengthAdjust=\"spacingAndGlyphs\"", num(over_panel));
  return fmt::format("<text x=\"{}\" y=\"{}\" font-weight=\"bold\"{}>{}</text>\n", num(start),
                     num(y + 20.0), squeeze, escape_xml(heading));
}

/// A panel with its top left corner at (`x`, `y`) titled `heading`, each cell as `paint`
/// gives it, and `backend`'s line on top.
std::string panel(const CaseResults& results, const std::string& backend,
                  const std::string& heading, double x, double y, const MapCellPaint& paint) {
  const Scene& scene = *results.scene;
  const MapAxis rows = map_rows(scene), columns = map_columns(scene);
  const double cell = cell_size(scene);
  const double left = x + kLeft, top = y + kTop;
  const std::size_t q = columns.values.size(), p = rows.values.size();
  std::string out = panel_title(heading, x, left, y, panel_width(scene));
  std::string marks;
  for (std::size_t r = 0; r < p; ++r)
    for (std::size_t c = 0; c < q; ++c) {
      const SweepPoint& point = results.sweep->points[rows.index[r] * q + columns.index[c]];
      const MapCell painted = paint(point);
      const double cx = left + static_cast<double>(c) * cell;
      const double cy = top + static_cast<double>(p - 1 - r) * cell;
      out += fmt::format(
          "<rect x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" fill=\"{}\"><title>{} = {}, {} = "
          "{}: {}</title></rect>\n",
          num(cx), num(cy), num(cell), num(cell), painted.fill, escape_xml(rows.parameter),
          short_number(rows.values[r]), escape_xml(columns.parameter),
          short_number(columns.values[c]), escape_xml(painted.words));
      marks += mark_svg(painted.mark, cx, cy, cell);
    }
  out += fmt::format(
      "<rect x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" fill=\"none\" stroke=\"#444444\"/>\n",
      num(left), num(top), num(cell * static_cast<double>(q)), num(cell * static_cast<double>(p)));
  // The theory's line, black on a white halo so that it shows on every colour.
  if (const std::string line = boundary_points(scene, backend, left, top, cell); !line.empty())
    for (const char* stroke : {"stroke=\"#ffffff\" stroke-width=\"5\"",
                               "stroke=\"#000000\" stroke-width=\"2\" stroke-dasharray=\"6 3\""})
      out += fmt::format("<polyline points=\"{}\" fill=\"none\" {}/>\n", line, stroke);
  return out + marks + axes(scene, left, top);
}

/// One backend's panel of its outcomes with its top left corner at (`x`, `y`).
std::string panel(const CaseResults& results, const std::string& backend, double x, double y) {
  const Scene& scene = *results.scene;
  const MapScale scale = map_scale(results);
  return panel(results, backend, backend, x, y, [&](const SweepPoint& point) {
    const RunRecord* run = run_at(point, backend);
    const MapOutcome outcome = map_outcome(scene, run);
    // A coloured map paints an ok run's error on the scale, and names it in the title.
    const std::optional<double> error = scaled_error(scale, run);
    return MapCell{error ? scale_fill(scale, *error) : outcome_fill(outcome),
                   map_outcome_name(outcome) +
                       (error ? ", " + scale.metric + " error " + short_number(*error) : ""),
                   MapMark::None};
  });
}

std::string opening(double width, double height, const std::string& title) {
  return fmt::format(
      "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{0}\" height=\"{1}\" viewBox=\"0 0 {0} "
      "{1}\" font-family=\"sans-serif\" font-size=\"12\">\n<rect width=\"100%\" height=\"100%\" "
      "fill=\"#ffffff\"/>\n<title>{2}</title>\n",
      num(width), num(height), escape_xml(title));
}

/// The legend's height: the outcomes and the line, and a colour map's bar under them.
double legend_height(const CaseResults& results, bool line) {
  return kLegendHeight + (line && !map_scale(results).metric.empty() ? 44.0 : 0.0);
}

/// The outcomes the legend names, each with its words (the onset's threshold stated).
std::vector<std::pair<MapOutcome, std::string>> legend_outcomes(const Scene& scene) {
  std::vector<MapOutcome> shown = {MapOutcome::Ok};
  if (!scene.sweep->onset.empty()) shown.push_back(MapOutcome::PastOnset);
  for (MapOutcome o : {MapOutcome::Diverged, MapOutcome::Unsupported, MapOutcome::Failed})
    shown.push_back(o);
  std::vector<std::pair<MapOutcome, std::string>> out;
  for (MapOutcome o : shown) {
    std::string name = map_outcome_name(o);
    if (o == MapOutcome::PastOnset)
      name += " (" + scene.sweep->onset + " > " + short_number(scene.sweep->onset_above) + ")";
    out.emplace_back(o, name);
  }
  return out;
}

/// The legend's width, px: its row of outcomes, or the line's words where they are longer.
double legend_width(const Scene& scene, const MapTheory* line) {
  double x = 12.0;
  for (const auto& [o, name] : legend_outcomes(scene))
    x += 28.0 + 6.5 * static_cast<double>(name.size());
  return line ? std::max(x, 58.0 + 6.5 * static_cast<double>(line->line.size())) : x;
}

/// The colours' meanings, in a row at `y`, the line's under it when one is drawn, and a
/// coloured map's bar under that.
std::string legend(const CaseResults& results, double y, const MapTheory* line,
                   bool with_scale = true) {
  const Scene& scene = *results.scene;
  std::string out;
  if (const MapScale scale = map_scale(results); with_scale && !scale.metric.empty())
    out += scale_legend(scale, 12.0, y + (line ? 48.0 : 22.0));
  double x = 12.0;
  for (const auto& [o, name] : legend_outcomes(scene)) {
    out += fmt::format(
        "<rect x=\"{}\" y=\"{}\" width=\"12\" height=\"12\" fill=\"{}\" stroke=\"#444444\"/>"
        "<text x=\"{}\" y=\"{}\">{}</text>\n",
        num(x), num(y), outcome_fill(o), num(x + 16.0), num(y + 10.5), escape_xml(name));
    x += 28.0 + 6.5 * static_cast<double>(name.size());
  }
  if (line == nullptr) return out;
  out += fmt::format(
      "<line x1=\"12\" y1=\"{0}\" x2=\"40\" y2=\"{0}\" stroke=\"#000000\" stroke-width=\"2\" "
      "stroke-dasharray=\"6 3\"/><text x=\"46\" y=\"{1}\">{2}</text>\n",
      num(y + 32.0), num(y + 36.0), escape_xml(line->line));
  return out;
}

}  // namespace

std::string map_panel(const CaseResults& results, const std::string& backend,
                      const std::string& heading, double x, double y, const MapCellPaint& paint) {
  return panel(results, backend, heading, x, y, paint);
}

std::string map_svg_opening(double width, double height, const std::string& title) {
  return opening(width, height, title);
}

std::string map_outcome_fill(MapOutcome outcome) {
  return outcome_fill(outcome);
}

std::string map_outcomes_legend(const CaseResults& results, double y, const std::string& backend) {
  return legend(results, y, map_theory(*results.scene, backend), false);
}

double map_panel_width(const Scene& scene) {
  return panel_width(scene);
}

double map_panel_height(const Scene& scene) {
  return panel_height(scene);
}

std::vector<std::string> map_backends(const CaseResults& results) {
  std::vector<std::string> out;
  for (const SweepPoint& p : results.sweep->points)
    for (const RunRecord& run : p.runs)
      if (std::find(out.begin(), out.end(), run.backend) == out.end()) out.push_back(run.backend);
  return out;
}

std::string map_file(const Scene& scene, const std::string& backend) {
  std::string name = backend;
  std::replace(name.begin(), name.end(), '/', '-');
  std::replace(name.begin(), name.end(), '+', '-');
  return scene.name + "-map-" + name + ".svg";
}

std::string map_multiples_file(const Scene& scene) {
  return scene.name + "-map.svg";
}

std::string boundary_points(const Scene& scene, const std::string& backend, double left, double top,
                            double cell) {
  const MapTheory* theory = map_theory(scene, backend);
  if (theory == nullptr) return "";
  const MapAxis rows = map_rows(scene), columns = map_columns(scene);
  const bool bound_across = columns.parameter == theory->bounded;
  const double rows_px = cell * static_cast<double>(rows.values.size());
  std::string out;
  for (const BoundaryPoint& b : map_boundary(scene, backend)) {
    const double along = axis_position(bound_across ? columns : rows, b.limit);
    const double at = axis_position(bound_across ? rows : columns, b.value);
    const double x = left + cell * (bound_across ? along : at);
    const double y = top + rows_px - cell * (bound_across ? at : along);
    out += (out.empty() ? "" : " ") + num(x) + "," + num(y);
  }
  return out;
}

std::string map_svg(const CaseResults& results, const std::string& backend) {
  const Scene& scene = *results.scene;
  const MapTheory* line = map_theory(scene, backend);
  const double width = std::max(panel_width(scene), legend_width(scene, line));
  const double height = panel_height(scene) + legend_height(results, line != nullptr);
  return opening(width, height, scene.name + ": the map of " + backend) +
         panel(results, backend, 0.0, 0.0) + legend(results, panel_height(scene), line) +
         "</svg>\n";
}

std::string map_multiples_svg(const CaseResults& results) {
  const Scene& scene = *results.scene;
  const std::vector<std::string> backends = map_backends(results);
  const std::size_t across = std::min(kPanelsPerRow, backends.size());
  const std::size_t down = (backends.size() + across - 1) / across;
  const double w = panel_width(scene), h = panel_height(scene);
  const MapTheory* line = nullptr;
  std::string panels;
  for (std::size_t i = 0; i < backends.size(); ++i) {
    panels += panel(results, backends[i], w * static_cast<double>(i % across),
                    h * static_cast<double>(i / across));
    if (line == nullptr) line = map_theory(scene, backends[i]);
  }
  const double width = std::max(w * static_cast<double>(across), legend_width(scene, line));
  const double height = h * static_cast<double>(down) + legend_height(results, line != nullptr);
  return opening(width, height, scene.name + ": every backend's map") + panels +
         legend(results, h * static_cast<double>(down), line) + "</svg>\n";
}

}  // namespace bb
