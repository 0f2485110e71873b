// Drawing with gnuplot: a plot's script and data written beside the SVG, gnuplot run
// without a shell, the SVG checked whole; and the pieces every plot of a page shares (a
// colour per backend, the reference thick and black, long series thinned).
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "files/file_batch.hpp"
#include "files/result_cache.hpp"
#include "report/plot_layout.hpp"
#include "run/results.hpp"

namespace bb {

/// Most points a series keeps when drawn.
inline constexpr std::size_t kMaxPlotPoints = 2000;

/// `s` as a gnuplot string literal.
std::string quote(const std::string& s);
/// Whether gnuplot can be run.
bool gnuplot_available();
/// Why gnuplot cannot be run ("" when it can): not found, or found and failed to start
/// (how it ended, and what it said).
std::string gnuplot_problem();
/// While one lives, draw() keeps each SVG in `cache` under a digest of what decides it (the
/// script, the data, the size and gnuplot's version) and, with `reuse`, takes a kept one
/// instead of running gnuplot again: an unchanged report redraws nothing.
class KeptDrawings {
 public:
  KeptDrawings(const ResultCache* cache, bool reuse);
  ~KeptDrawings();
  KeptDrawings(const KeptDrawings&) = delete;
  KeptDrawings& operator=(const KeptDrawings&) = delete;

 private:
  const ResultCache* previous_cache_;
  bool previous_reuse_;
};

/// Runs `script_body` (which reads the file `data` names) and writes the SVG as `name`
/// into `batch`, `height` pixels tall. Returns an error for a plot there is nothing to
/// draw; throws WriteError when a file could not be written.
std::string draw(const std::string& script_body, const std::string& data, FileBatch& batch,
                 const std::string& name, int height = 600);
/// Runs at report_dt that produced samples, the reference first.
std::vector<const RunRecord*> report_runs(const CaseResults& results);
/// How series `i` of `backend` is drawn, in the backend's own style (backend_style.hpp):
/// gnuplot's "with ..." clause.
std::string series_style(std::size_t i, const std::string& backend);
/// The plot clause of series `i` of `backend` in data block `block`, drawn in the backend's
/// own style (backend_style.hpp); `titled` false leaves it out of the legend (a second body
/// of the same backend on a shared panel).
std::string series_line(std::size_t i, int block, const std::string& backend, bool titled = true);
/// The rows "t value" of one series, thinned for drawing.
std::string series_rows(const std::vector<double>& times, const std::vector<double>& values);
/// Indices of the points of `values` to draw: all of them up to `max_points`, else per
/// bucket the lowest and the highest, in order, and always the first and the last.
std::vector<std::size_t> thinned(const std::vector<double>& values, std::size_t max_points);

/// A page of rows of two panels against time, every run in each panel with the reference
/// first (thick and black), each panel named above it, one legend in a band of its own
/// right of both columns (plot_layout.hpp).
class TwoColumnPlot {
 public:
  /// `x_label` names the horizontal axis of every panel.
  explicit TwoColumnPlot(std::string title, std::string x_label = "t (s)")
      : title_(std::move(title)), x_label_(std::move(x_label)) {}
  /// Adds run `i` (its place among report_runs) to the current row's left or right panel.
  void add(bool right, std::size_t i, const std::string& backend, const std::vector<double>& times,
           const std::vector<double>& values);
  /// A panel's vertical axis, set when a run off the others' scale is cut at its edge.
  using Window = std::optional<std::pair<double, double>>;
  /// Every panel's horizontal axis from `lo` to `hi` (else each panel scales its own).
  void set_x_range(double lo, double hi) { x_range_ = std::pair{lo, hi}; }
  /// Ends the current row, its panels named `left_label` and `right_label`, each scaled to
  /// its window when it has one; a row without series is left out.
  void end_row(const std::string& left_label, const std::string& right_label,
               const Window& left_window = std::nullopt, const Window& right_window = std::nullopt);
  /// Draws the rows as `name` into `batch`; returns why there is nothing to draw, else "".
  std::string draw_into(FileBatch& batch, const std::string& name) const;

 private:
  struct Row {
    std::string left_label, right_label, left, right;
    Window left_window, right_window;
  };
  std::string title_, x_label_, data_, left_, right_;
  Window x_range_;
  std::vector<LegendEntry> legend_, left_titles_;
  std::vector<Row> rows_;
  int block_ = 0;
};

}  // namespace bb
