// Pictures the tests look at: a PNG read back (through libpng, where the build found it),
// an SVG rendered by rsvg-convert, and the layout of a gnuplot SVG (its panels and its
// legend's entries) read from its elements.
#pragma once

#include <gtest/gtest.h>
#if BB_HAVE_PNG
#include <png.h>
#endif

#include <cstdlib>
#include <regex>
#include <string>
#include <vector>

namespace bb::test {

/// An RGBA image, or empty when the file could not be read.
struct Image {
  int width = 0, height = 0;
  std::vector<unsigned char> rgba;
  const unsigned char* at(int x, int y) const { return &rgba[4 * (y * width + x)]; }
};

/// Why pictures cannot be looked at here (rsvg-convert or libpng missing), or "".
inline std::string why_no_pictures() {
#if !BB_HAVE_PNG
  return "libpng-dev was not found when the tests were built (scripts/setup --tests installs it)";
#else
  if (std::system("rsvg-convert --version > /dev/null 2>&1") != 0)
    return "rsvg-convert is not installed (scripts/setup --tests installs librsvg2-bin)";
  return "";
#endif
}

inline Image read_png([[maybe_unused]] const std::string& path) {
  Image out;
#if BB_HAVE_PNG
  png_image image{};
  image.version = PNG_IMAGE_VERSION;
  if (!png_image_begin_read_from_file(&image, path.c_str())) return out;
  image.format = PNG_FORMAT_RGBA;
  out.rgba.resize(PNG_IMAGE_SIZE(image));
  if (!png_image_finish_read(&image, nullptr, out.rgba.data(), 0, nullptr)) return {};
  out.width = static_cast<int>(image.width);
  out.height = static_cast<int>(image.height);
#endif
  return out;
}

/// A rectangle of an SVG picture, in its pixels (y down).
struct Box {
  double x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  bool overlaps(const Box& o) const { return x0 < o.x1 && o.x0 < x1 && y0 < o.y1 && o.y0 < y1; }
};

/// Where a gnuplot SVG puts its panels and its legend.
struct GnuplotLayout {
  std::vector<Box> panels;  ///< each panel's plotting area, inside its border
  struct Entry {
    std::string title;
    Box box;  ///< the entry's sample and text
  };
  std::vector<Entry> legend;
};

/// About the width of `text` in DejaVu Sans (Debian's "sans") at `size`: its lower-case
/// letters, digits and punctuation average about 0.6 em, its capitals and m, w about 0.9.
inline double text_width(const std::string& text, double size) {
  double em = 0.0;
  for (char c : text) em += (c >= 'A' && c <= 'Z') || c == 'm' || c == 'w' ? 0.9 : 0.6;
  return em * size;
}

/// A line of text of a gnuplot SVG, where it is anchored.
struct SvgText {
  std::string text, anchor;  ///< anchor: "start", "middle" or "end"
  double x = 0, y = 0, size = 0;
  bool turned = false;  ///< drawn on its side (a y label)
};

/// A number of an SVG's attributes, as a group.
inline const std::string kSvgNumber = R"re((-?[0-9.]+))re";

/// A line of gnuplot's text: its position (1, 2), whether it is turned (3), its size (4),
/// its anchor (5) and the text (6).
inline const std::regex& svg_text_pattern() {
  static const std::regex pattern(
      R"re(<g transform="translate\()re" + kSvgNumber + "," + kSvgNumber +
      R"re(\)( rotate\([0-9-]+\))?" stroke="none" fill="black" font-family="[^"]*" font-size=")re" +
      kSvgNumber + R"re("\s+text-anchor="(start|middle|end)">\s*<text>([^<]*)</text>)re");
  return pattern;
}

/// Every line of text of a gnuplot SVG.
inline std::vector<SvgText> svg_texts(const std::string& svg) {
  std::vector<SvgText> out;
  for (std::sregex_iterator it(svg.begin(), svg.end(), svg_text_pattern()), end; it != end; ++it)
    out.push_back({(*it)[6], (*it)[5], std::stod((*it)[1]), std::stod((*it)[2]),
                   std::stod((*it)[4]), (*it)[3].matched});
  return out;
}

/// The layout of a gnuplot SVG: the borders drawn as closed rectangles are the panels; in
/// each plot's group (`gnuplot_plot_...`), the text before its first path is its legend
/// entry, and that path's first stroke is the entry's sample.
inline GnuplotLayout gnuplot_layout(const std::string& svg) {
  GnuplotLayout out;
  const std::string& n = kSvgNumber;
  const std::regex border("d='M" + n + "," + n + " L" + n + "," + n + " L" + n + "," + n + " L" +
                          n + "," + n + " L" + n + "," + n + " Z");
  for (std::sregex_iterator it(svg.begin(), svg.end(), border), end; it != end; ++it) {
    const auto v = [&](int i) { return std::stod((*it)[i].str()); };
    // M x0,y0 L x0,y1 L x1,y1 L x1,y0 L x0,y0 Z: an axis-aligned rectangle.
    if (v(1) == v(3) && v(4) == v(6) && v(5) == v(7) && v(2) == v(8) && v(1) == v(9))
      out.panels.push_back(
          {std::min(v(1), v(5)), std::min(v(2), v(4)), std::max(v(1), v(5)), std::max(v(2), v(4))});
  }
  const std::regex sample("d='M" + n + "," + n + " L" + n + "," + n);
  for (std::size_t at = svg.find("<g id=\"gnuplot_plot_"); at != std::string::npos;) {
    const std::size_t next = svg.find("<g id=\"gnuplot_plot_", at + 1);
    const std::string group = svg.substr(at, next == std::string::npos ? next : next - at);
    at = next;
    // A titled plot draws its entry before its first path; an untitled one has none.
    const std::string head = group.substr(0, group.find("<path"));
    std::smatch t, s;
    if (!std::regex_search(head, t, svg_text_pattern())) continue;
    const double x = std::stod(t[1]), y = std::stod(t[2]), size = std::stod(t[4]);
    const double w = text_width(t[6], size);
    const double left = t[5] == "start" ? x : t[5] == "end" ? x - w : x - w / 2;
    Box box{left, y - size, left + w, y + 0.3 * size};
    const std::string after = group.substr(head.size());
    if (std::regex_search(after, s, sample) && std::stod(s[2]) == std::stod(s[4])) {
      box.x0 = std::min({box.x0, std::stod(s[1]), std::stod(s[3])});
      box.x1 = std::max({box.x1, std::stod(s[1]), std::stod(s[3])});
    }
    out.legend.push_back({t[6], box});
  }
  return out;
}

}  // namespace bb::test
