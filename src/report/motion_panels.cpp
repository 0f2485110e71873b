#include "report/motion_panels.hpp"

#include <fmt/format.h>

namespace bb::motion {

std::string open_panel(const Panel& p, const Canvas& c) {
  const double top = p.title.empty() ? p.y : p.y + kPanelTitle;
  std::string out;
  if (!p.title.empty())
    out += fmt::format("<text x=\"{}\" y=\"{}\" font-weight=\"bold\">{}</text>\n", num(p.x),
                       num(p.y + 13.0), p.title);
  return out + fmt::format(
                   "<svg x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" viewBox=\"0 0 {} {}\" "
                   "overflow=\"hidden\">\n<rect width=\"100%\" height=\"100%\" fill=\"#ffffff\" "
                   "stroke=\"#dddddd\"/>\n",
                   num(p.x), num(top), num(p.width), num(c.height * p.width / c.width),
                   num(c.width), num(c.height));
}

double panel_height(const Panel& p, const Canvas& c) {
  return (p.title.empty() ? 0.0 : kPanelTitle) + c.height * p.width / c.width;
}

std::vector<Panel> layout(std::size_t count, bool multiples, const Canvas& c, double columns,
                          double top) {
  std::vector<Panel> out;
  if (!multiples) {
    out.push_back({kMargin, top, kCanvasWidth, ""});
    return out;
  }
  const double width = (kCanvasWidth - (columns - 1) * kGap) / columns;
  const double height = kPanelTitle + c.height * width / c.width + kGap;
  for (std::size_t i = 0; i < count; ++i) {
    const std::size_t col = i % static_cast<std::size_t>(columns);
    const std::size_t row = i / static_cast<std::size_t>(columns);
    out.push_back({kMargin + col * (width + kGap), top + row * height, width, ""});
  }
  return out;
}

}  // namespace bb::motion
