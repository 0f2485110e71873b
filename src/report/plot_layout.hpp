// Where things go on a gnuplot picture, so that nothing covers the data and nothing runs off
// the picture: the legend in a band of its own right of the panels, as wide as its longest
// entry and tall enough for every entry in one column; notes and titles wrapped to lines
// that fit the picture's width.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace bb {

/// Width of every gnuplot picture, in pixels.
inline constexpr int kPlotWidth = 960;
/// Pixels per line of the legend (gnuplot's row height at the terminal's font).
inline constexpr int kLegendRowPixels = 15;

/// One entry of a legend: its title, and how its line is drawn (gnuplot's "with ...").
struct LegendEntry {
  std::string title, style;
};

/// The legend's band, right of the panels.
struct LegendBand {
  double panels_right = 0.0;  ///< screen fraction where the panels' plotting area must end
  double left = 0.0;          ///< screen fraction of the legend's left edge
  int top = 0;                ///< pixels from the picture's top to the legend's
  int height = 0;             ///< pixels the picture needs to hold the legend below `top`
  std::vector<LegendEntry> entries;
  /// The legend as a plot of its own over the band, to be drawn last in a multiplot on a
  /// picture `picture_height` pixels tall: its entries (gnuplot's keyentry) and nothing
  /// else. A panel's own key is limited to the rows its height holds; this one holds them
  /// all. "" without entries.
  std::string plot(int picture_height) const;
};

/// The band for `entries`, its top `top` pixels below the picture's top: the legend starts
/// at the band's left edge and reads rightwards, one column of every entry, and the band is
/// as wide as the longest title in the legend's font (an upper bound of the glyphs'
/// width), so the panels that end at `panels_right` never lie under it.
LegendBand legend_band(std::vector<LegendEntry> entries, int top);

/// An upper bound, in pixels, of the width of `text` drawn in a sans font of `font_size`.
double text_width_bound(const std::string& text, double font_size);

/// `text` broken at spaces into lines no wider than `pixels` in a sans font of `font_size`
/// (text_width_bound; a longer word stands on a line of its own).
std::vector<std::string> wrapped(const std::string& text, double pixels, double font_size);

/// `lead` then `items`, separated by ", ", in lines no wider than `pixels`: a line breaks
/// between two items, never inside one that fits on a line.
std::vector<std::string> wrapped_items(const std::string& lead,
                                       const std::vector<std::string>& items, double pixels,
                                       double font_size);

/// `lines` as one gnuplot string literal, one line under another.
std::string quote_lines(const std::vector<std::string>& lines);

}  // namespace bb
