// Pictures the tests look at: a PNG read back (through libpng, where the build found it),
// an SVG rendered by rsvg-convert, and the layout of a gnuplot SVG (its panels and its
// legend's entries) read from its elements.
#pragma once

#include <gtest/gtest.h>
#if BB_HAVE_PNG
#include <png.h>
#endif

#include <algorithm>
#include <array>
#include <cstdlib>
#include <optional>
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

/// Reads a gnuplot SVG's attributes by hand, left to right. (No std::regex: it trips GCC
/// 12's maybe-uninitialized warning in the sanitizer build, an error there.)
struct SvgCursor {
  const std::string& s;
  std::size_t at = 0;
  /// Takes `text` if it comes next.
  bool take(const std::string& text) {
    if (s.compare(at, text.size(), text) != 0) return false;
    at += text.size();
    return true;
  }
  /// Takes a number (digits, '.', a leading '-').
  bool number(double& v) {
    std::size_t end = at;
    if (end < s.size() && s[end] == '-') ++end;
    while (end < s.size() && ((s[end] >= '0' && s[end] <= '9') || s[end] == '.')) ++end;
    if (end == at || (end == at + 1 && s[at] == '-')) return false;
    v = std::stod(s.substr(at, end - at));
    at = end;
    return true;
  }
  /// Takes everything up to `stop` (not included) into `out`.
  bool until(char stop, std::string& out) {
    const std::size_t end = s.find(stop, at);
    if (end == std::string::npos) return false;
    out = s.substr(at, end - at);
    at = end;
    return true;
  }
  void spaces() {
    while (at < s.size() && (s[at] == ' ' || s[at] == '\n' || s[at] == '\t')) ++at;
  }
  /// Takes "x,y".
  bool point(double& x, double& y) { return number(x) && take(",") && number(y); }
};

/// The line of gnuplot's text whose group starts at `at` in `svg`, if it is one.
inline std::optional<SvgText> svg_text_at(const std::string& svg, std::size_t at) {
  SvgCursor c{svg, at};
  SvgText t;
  std::string skipped;
  if (!c.take("<g transform=\"translate(") || !c.point(t.x, t.y) || !c.take(")")) return {};
  if (c.take(" rotate(")) {
    if (!c.until(')', skipped) || !c.take(")")) return {};
    t.turned = true;
  }
  if (!c.take("\" stroke=\"none\" fill=\"black\" font-family=\"") || !c.until('"', skipped) ||
      !c.take("\" font-size=\"") || !c.number(t.size) || !c.take("\""))
    return {};
  c.spaces();
  if (!c.take("text-anchor=\"") || !c.until('"', t.anchor) || !c.take("\">")) return {};
  if (t.anchor != "start" && t.anchor != "middle" && t.anchor != "end") return {};
  c.spaces();
  if (!c.take("<text>") || !c.until('<', t.text) || !c.take("</text>")) return {};
  return t;
}

/// Every line of text of a gnuplot SVG.
inline std::vector<SvgText> svg_texts(const std::string& svg) {
  std::vector<SvgText> out;
  for (std::size_t at = svg.find("<g transform="); at != std::string::npos;
       at = svg.find("<g transform=", at + 1))
    if (const auto t = svg_text_at(svg, at)) out.push_back(*t);
  return out;
}

/// The first stroke "d='M x,y L x,y" in `text`: its two points, x0 y0 x1 y1.
inline std::optional<std::array<double, 4>> first_stroke(const std::string& text) {
  for (std::size_t at = text.find("d='M"); at != std::string::npos;
       at = text.find("d='M", at + 1)) {
    SvgCursor c{text, at + 4};
    std::array<double, 4> v{};
    if (c.point(v[0], v[1]) && c.take(" L") && c.point(v[2], v[3])) return v;
  }
  return std::nullopt;
}

/// The layout of a gnuplot SVG: the borders drawn as closed rectangles are the panels; in
/// each plot's group (`gnuplot_plot_...`), the text before its first path is its legend
/// entry, and that path's first stroke is the entry's sample.
inline GnuplotLayout gnuplot_layout(const std::string& svg) {
  GnuplotLayout out;
  for (std::size_t at = svg.find("d='M"); at != std::string::npos; at = svg.find("d='M", at + 1)) {
    // M x0,y0 L x0,y1 L x1,y1 L x1,y0 L x0,y0 Z: an axis-aligned rectangle.
    SvgCursor c{svg, at + 4};
    double v[10];
    bool ok = c.point(v[0], v[1]);
    for (int k = 1; ok && k < 5; ++k) ok = c.take(" L") && c.point(v[2 * k], v[2 * k + 1]);
    if (!ok || !c.take(" Z")) continue;
    if (v[0] == v[2] && v[3] == v[5] && v[4] == v[6] && v[1] == v[7] && v[0] == v[8])
      out.panels.push_back(
          {std::min(v[0], v[4]), std::min(v[1], v[3]), std::max(v[0], v[4]), std::max(v[1], v[3])});
  }
  for (std::size_t at = svg.find("<g id=\"gnuplot_plot_"); at != std::string::npos;) {
    const std::size_t next = svg.find("<g id=\"gnuplot_plot_", at + 1);
    const std::string group = svg.substr(at, next == std::string::npos ? next : next - at);
    at = next;
    // A titled plot draws its entry before its first path; an untitled one has none.
    const std::string head = group.substr(0, group.find("<path"));
    const std::vector<SvgText> texts = svg_texts(head);
    if (texts.empty()) continue;
    const SvgText& t = texts.front();
    const double w = text_width(t.text, t.size);
    const double left = t.anchor == "start" ? t.x : t.anchor == "end" ? t.x - w : t.x - w / 2;
    Box box{left, t.y - t.size, left + w, t.y + 0.3 * t.size};
    if (const auto s = first_stroke(group.substr(head.size())); s && (*s)[1] == (*s)[3]) {
      box.x0 = std::min({box.x0, (*s)[0], (*s)[2]});
      box.x1 = std::max({box.x1, (*s)[0], (*s)[2]});
    }
    out.legend.push_back({t.text, box});
  }
  return out;
}

}  // namespace bb::test
