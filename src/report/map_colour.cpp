#include "report/map_colour.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>

#include "report/xml_text.hpp"

namespace bb {

namespace {

/// ColorBrewer's YlGnBu, nine classes: light for small errors, dark for large.
constexpr std::array<std::array<int, 3>, 9> kStops = {{{255, 255, 217},
                                                       {237, 248, 177},
                                                       {199, 233, 180},
                                                       {127, 205, 187},
                                                       {65, 182, 196},
                                                       {29, 145, 192},
                                                       {34, 94, 168},
                                                       {37, 52, 148},
                                                       {8, 29, 88}}};

/// The colour bar's size, px, and how many swatches make it.
constexpr double kBarWidth = 180.0, kBarHeight = 12.0;
constexpr int kBarSwatches = 36;

/// Where `error` lies on the scale, 0 at its low end to 1 at its high end.
double scale_position(const MapScale& scale, double error) {
  if (!(scale.high > scale.low)) return error >= scale.high ? 1.0 : 0.0;
  const double t = scale.logarithmic ? std::log(std::max(error, scale.low) / scale.low) /
                                           std::log(scale.high / scale.low)
                                     : (error - scale.low) / (scale.high - scale.low);
  return std::clamp(t, 0.0, 1.0);
}

std::string colour_at(double t) {
  const double at = t * static_cast<double>(kStops.size() - 1);
  const std::size_t k = std::min(static_cast<std::size_t>(at), kStops.size() - 2);
  const double f = at - static_cast<double>(k);
  std::array<int, 3> c{};
  for (std::size_t i = 0; i < 3; ++i)
    c[i] = static_cast<int>(std::lround(kStops[k][i] + f * (kStops[k + 1][i] - kStops[k][i])));
  return fmt::format("#{:02x}{:02x}{:02x}", c[0], c[1], c[2]);
}

}  // namespace

MapScale map_scale(const CaseResults& results) {
  MapScale scale;
  if (!results.sweep || results.scene->sweep->colour.empty()) return scale;
  const std::string metric = results.scene->sweep->colour;
  bool any = false;
  for (const SweepPoint& p : results.sweep->points)
    for (const RunRecord& run : p.runs)
      if (const std::optional<double> e =
              run.status == RunStatus::Ok ? metric_value(run, metric) : std::nullopt;
          e && *e > 0.0 && std::isfinite(*e)) {
        scale.low = any ? std::min(scale.low, *e) : *e;
        scale.high = any ? std::max(scale.high, *e) : *e;
        any = true;
      }
  if (!any) return scale;
  scale.metric = metric;
  scale.logarithmic = scale.high > 10.0 * scale.low;
  return scale;
}

std::optional<double> scaled_error(const MapScale& scale, const RunRecord* run) {
  if (scale.metric.empty() || run == nullptr || run->status != RunStatus::Ok) return std::nullopt;
  return metric_value(*run, scale.metric);
}

std::string scale_fill(const MapScale& scale, double error) {
  return colour_at(scale_position(scale, error));
}

std::string scale_legend(const MapScale& scale, double x, double y) {
  std::string out =
      fmt::format("<text x=\"{:.2f}\" y=\"{:.2f}\">{} error{}</text>\n", x, y + 10.0,
                  escape_xml(scale.metric), scale.logarithmic ? " (logarithmic)" : "");
  const double bar_x = x, bar_y = y + 16.0, w = kBarWidth / kBarSwatches;
  for (int i = 0; i < kBarSwatches; ++i)
    out += fmt::format(
        "<rect x=\"{:.2f}\" y=\"{:.2f}\" width=\"{:.2f}\" height=\"{:.2f}\" fill=\"{}\"/>\n",
        bar_x + i * w, bar_y, w, kBarHeight, colour_at((i + 0.5) / kBarSwatches));
  out += fmt::format(
      "<rect x=\"{:.2f}\" y=\"{:.2f}\" width=\"{:.2f}\" height=\"{:.2f}\" fill=\"none\" "
      "stroke=\"#444444\"/>\n<text x=\"{:.2f}\" y=\"{:.2f}\" font-size=\"10\">{}</text>\n<text "
      "x=\"{:.2f}\" y=\"{:.2f}\" font-size=\"10\" text-anchor=\"end\">{}</text>\n",
      bar_x, bar_y, kBarWidth, kBarHeight, bar_x, bar_y + kBarHeight + 11.0,
      fmt::format("{:.3g} or less", scale.low), bar_x + kBarWidth, bar_y + kBarHeight + 11.0,
      fmt::format("{:.3g}", scale.high));
  return out;
}

}  // namespace bb
