#include "report/map_difference_picture.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "report/map_cells.hpp"
#include "report/map_difference.hpp"
#include "report/map_picture.hpp"
#include "report/xml_text.hpp"
#include "study/backend_names.hpp"

namespace bb {

namespace {

/// Most panels side by side, and the legend's height, as in the outcomes' small multiples.
constexpr std::size_t kDifferencePanelsPerRow = 4;
constexpr double kDifferenceLegendHeight = 64.0;

const char* difference_fill(MapDifference difference) {
  switch (difference) {
    case MapDifference::Same:
      return "#deebf7";
    case MapDifference::Differs:
      return "#08519c";
    case MapDifference::NoReference:
    case MapDifference::NotRun:
      break;
  }
  return "#ffffff";
}

MapMark difference_mark(MapDifference difference) {
  return difference == MapDifference::NoReference ? MapMark::Question : MapMark::None;
}

/// The legend's row at `y`, and the theory's line under it when a panel draws one.
std::string differences_legend(double y, bool line) {
  std::string out;
  double x = 12.0;
  for (MapDifference d : {MapDifference::Differs, MapDifference::Same, MapDifference::NoReference,
                          MapDifference::NotRun}) {
    const std::string name =
        map_difference_name(d) + (d == MapDifference::NoReference ? " (?)" : "");
    out += fmt::format(
        "<rect x=\"{:.2f}\" y=\"{:.2f}\" width=\"12\" height=\"12\" fill=\"{}\" "
        "stroke=\"#444444\"/><text x=\"{:.2f}\" y=\"{:.2f}\">{}</text>\n",
        x, y, difference_fill(d), x + 16.0, y + 10.5, escape_xml(name));
    x += 28.0 + 6.5 * static_cast<double>(name.size());
  }
  if (!line) return out;
  return out + fmt::format(
                   "<line x1=\"12\" y1=\"{0:.2f}\" x2=\"40\" y2=\"{0:.2f}\" stroke=\"#000000\" "
                   "stroke-width=\"2\" stroke-dasharray=\"6 3\"/><text x=\"46\" y=\"{1:.2f}\">the "
                   "course theory's largest stable step, as on the outcomes' maps</text>\n",
                   y + 32.0, y + 36.0);
}

}  // namespace

std::string map_differences_svg(const CaseResults& results) {
  const Scene& scene = *results.scene;
  std::vector<std::string> backends = map_backends(results);
  backends.erase(std::remove(backends.begin(), backends.end(), kReferenceName), backends.end());
  if (backends.empty()) return "";
  const std::size_t across = std::min(kDifferencePanelsPerRow, backends.size());
  const std::size_t down = (backends.size() + across - 1) / across;
  const double w = map_panel_width(scene), h = map_panel_height(scene);
  std::string out = map_svg_opening(std::max(w * static_cast<double>(across), 620.0),
                                    h * static_cast<double>(down) + kDifferenceLegendHeight,
                                    scene.name + ": where each backend differs from the reference");
  bool line = false;
  for (std::size_t i = 0; i < backends.size(); ++i) {
    const std::string& backend = backends[i];
    out +=
        map_panel(results, backend, backend, w * static_cast<double>(i % across),
                  h * static_cast<double>(i / across), [&](const SweepPoint& point) {
                    const MapDifference d = map_difference(scene, point, backend);
                    return MapCell{difference_fill(d), map_difference_words(scene, point, backend),
                                   difference_mark(d)};
                  });
    line = line || !map_boundary(scene, backend).empty();
  }
  return out + differences_legend(h * static_cast<double>(down), line) + "</svg>\n";
}

}  // namespace bb
