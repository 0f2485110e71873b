#include "report/plot_layout.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>

#include "report/gnuplot.hpp"

namespace bb {

namespace {

/// The legend's font size, in points (pixels on gnuplot's SVG).
constexpr double kLegendFont = 10.0;
/// From the legend's left edge to the start of its text: gnuplot's sample (samplen 2) and
/// the gaps either side of it, at the terminal's character width.
constexpr double kSampleAndGaps = 40.0;
/// Clear pixels left of the legend and right of it.
constexpr double kBandMargin = 12.0;

}  // namespace

double text_width_bound(const std::string& text, double font_size) {
  // DejaVu Sans (what "sans" is on Debian) is at most 0.64 em wide in its lower case, digits
  // and punctuation, at most 1.0 em in its capitals and m, w: a bound, never an estimate
  // that a wide name could exceed.
  double em = 0.0;
  for (char c : text)
    em += std::isupper(static_cast<unsigned char>(c)) || c == 'm' || c == 'w' ? 1.0 : 0.64;
  return em * font_size;
}

LegendBand legend_band(std::vector<LegendEntry> entries, int top) {
  double widest = 0.0;
  for (const LegendEntry& e : entries)
    widest = std::max(widest, text_width_bound(e.title, kLegendFont));
  const double width = kSampleAndGaps + widest + 2 * kBandMargin;
  LegendBand band;
  band.panels_right = (kPlotWidth - width) / kPlotWidth;
  band.left = (kPlotWidth - width + kBandMargin) / kPlotWidth;
  band.top = top;
  band.height = top + kLegendRowPixels * static_cast<int>(entries.size() + 1);
  band.entries = std::move(entries);
  return band;
}

std::string LegendBand::plot(int picture_height) const {
  if (entries.empty()) return "";
  const double top_at = 1.0 - static_cast<double>(top) / picture_height;
  // An empty plot over the band: no border, tics or grid; a constant below its range (a
  // plot of key entries alone trips an assertion of gnuplot 5.4).
  std::string out = fmt::format(
      "unset label\nunset logscale\nunset border\nunset tics\nunset grid\nunset xlabel\n"
      "unset ylabel\nunset title\nset lmargin at screen {0:.4f}\nset rmargin at screen "
      "0.995\nset tmargin at screen {1:.4f}\nset bmargin at screen 0.005\nset xrange [0:1]\n"
      "set yrange [0:1]\n"
      // One column (maxrows: every entry), read from the left edge rightwards: the sample,
      // then the name.
      "set key at screen {0:.4f}, screen {1:.4f} left top Left reverse samplen 2 maxrows {2} "
      "font \",{3}\"\nplot -1 notitle with lines lc rgb \"white\"",
      left, top_at, entries.size(), kLegendFont);
  for (const LegendEntry& e : entries)
    out += ", \\\n     keyentry " + e.style + " title " + quote(e.title);
  return out + "\n";
}

std::vector<std::string> wrapped(const std::string& text, double pixels, double font_size) {
  std::vector<std::string> lines;
  std::string line;
  std::size_t at = 0;
  while (at < text.size()) {
    std::size_t end = text.find(' ', at);
    if (end == std::string::npos) end = text.size();
    const std::string word = text.substr(at, end - at);
    if (!line.empty() && text_width_bound(line + " " + word, font_size) > pixels) {
      lines.push_back(line);
      line.clear();
    }
    line += (line.empty() ? "" : " ") + word;
    at = end + 1;
  }
  if (!line.empty()) lines.push_back(line);
  return lines;
}

std::vector<std::string> wrapped_items(const std::string& lead,
                                       const std::vector<std::string>& items, double pixels,
                                       double font_size) {
  std::vector<std::string> lines;
  std::string line = lead;
  for (std::size_t i = 0; i < items.size(); ++i) {
    const std::string piece = items[i] + (i + 1 < items.size() ? "," : "");
    const std::string joined = line + (line.empty() ? "" : " ") + piece;
    if (line.empty() || text_width_bound(joined, font_size) <= pixels) {
      line = joined;
      continue;
    }
    lines.push_back(line);
    // An item too long for a line of its own is broken at its spaces.
    std::vector<std::string> own = wrapped(piece, pixels, font_size);
    line = own.back();
    own.pop_back();
    lines.insert(lines.end(), own.begin(), own.end());
  }
  if (!line.empty()) lines.push_back(line);
  return lines;
}

std::string quote_lines(const std::vector<std::string>& lines) {
  std::string out;
  for (const std::string& line : lines) {
    const std::string q = quote(line);
    out += out.empty() ? q.substr(0, q.size() - 1) : "\\n" + q.substr(1, q.size() - 2);
  }
  return out.empty() ? "\"\"" : out + "\"";
}

}  // namespace bb
