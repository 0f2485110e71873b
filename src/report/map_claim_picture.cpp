#include "report/map_claim_picture.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "model/text.hpp"
#include "report/map_cells.hpp"
#include "report/map_picture.hpp"
#include "report/xml_text.hpp"
#include "run/region_claims.hpp"

namespace bb {

namespace {

/// The marks' legend and the verdict, under the outcomes' legend (64 px) at `y`.
constexpr double kClaimLegendHeight = 64.0 + 56.0;
/// The least width: the outcomes' legend in one row.
constexpr double kClaimWidth = 860.0;

/// The mark a point of the claim's picture carries.
MapMark claim_mark(const RegionPoint& point) {
  if (point.judged && !point.held) return MapMark::Cross;
  if (point.place == RegionPlace::WithinMargin) return MapMark::Ring;
  if (!ran_to_an_outcome(point.outcome)) return MapMark::Question;
  return MapMark::None;
}

/// What a point's tooltip says: its outcome, the boundary on `theory`'s axis, and what the
/// claim makes of it.
std::string claim_words(const RegionPoint& point, const MapTheory* theory) {
  std::string out = map_outcome_name(point.outcome);
  if (point.boundary && theory)
    out += "; the region's boundary at " + theory->bounded + " = " +
           map_bound_text(*theory, *point.boundary);
  if (point.judged) return out + (point.held ? ": the claim holds" : ": the claim fails");
  if (point.place == RegionPlace::WithinMargin) return out + ": within the margin, not judged";
  return out + ": not judged";
}

std::string marks_legend(double y, const std::string& verdict) {
  std::string out;
  double x = 12.0;
  for (const auto& [mark, name] :
       {std::pair{MapMark::Cross, "the claim fails here"},
        std::pair{MapMark::Ring, "within the claim's margin of the boundary: not judged"},
        std::pair{MapMark::Question, "no outcome to judge"}}) {
    out += fmt::format(
        "<rect x=\"{:.2f}\" y=\"{:.2f}\" width=\"14\" height=\"14\" fill=\"#ffffff\" "
        "stroke=\"#444444\"/>",
        x, y - 1.0);
    if (mark == MapMark::Cross)
      out += fmt::format(
          "<path d=\"M{0:.2f},{1:.2f} L{2:.2f},{3:.2f} M{0:.2f},{3:.2f} L{2:.2f},{1:.2f}\" "
          "stroke=\"#000000\" stroke-width=\"2\"/>",
          x + 3.0, y + 2.0, x + 11.0, y + 10.0);
    if (mark == MapMark::Ring)
      out += fmt::format(
          "<circle cx=\"{:.2f}\" cy=\"{:.2f}\" r=\"4\" fill=\"none\" stroke=\"#000000\" "
          "stroke-width=\"1.5\"/>",
          x + 7.0, y + 6.0);
    if (mark == MapMark::Question)
      out += fmt::format("<text x=\"{:.2f}\" y=\"{:.2f}\" text-anchor=\"middle\">?</text>", x + 7.0,
                         y + 10.5);
    out += fmt::format("<text x=\"{:.2f}\" y=\"{:.2f}\">{}</text>\n", x + 20.0, y + 10.5,
                       escape_xml(name));
    x += 34.0 + 6.5 * std::string(name).size();
  }
  return out + fmt::format("<text x=\"12\" y=\"{:.2f}\" font-weight=\"bold\">{}</text>\n", y + 36.0,
                           escape_xml(verdict));
}

}  // namespace

std::string map_claim_file(const Scene& scene, std::size_t k) {
  return scene.name + "-claim-" + std::to_string(k + 1) + ".svg";
}

std::string map_claim_svg(const CaseResults& results, const ClaimResult& claim) {
  const Scene& scene = *results.scene;
  const RegionClaim& g = *claim.claim->region;
  const std::vector<RegionPoint> points = region_points(results, *claim.claim);
  const MapTheory* theory = map_theory(scene, g.backend);
  const std::string verdict =
      claim.verdicts.empty() ? "" : claim.claim->text + ": " + claim.verdicts.front().verdict;
  const double w = map_panel_width(scene), h = map_panel_height(scene);
  // As wide as the outcomes' legend in one row, and as the verdict's line (bold, from x = 12).
  const double width =
      std::max({w, kClaimWidth, kMapBoldCharWidth * static_cast<double>(verdict.size()) + 24.0});
  std::string out =
      map_svg_opening(width, h + kClaimLegendHeight, scene.name + ": " + claim.claim->text);
  // The panel draws the points row by row ascending; each is found by its place in the list.
  out += map_panel(results, g.backend, g.backend, 0.0, 0.0, [&](const SweepPoint& at) {
    const RegionPoint& point = points[static_cast<std::size_t>(&at - results.sweep->points.data())];
    return MapCell{map_outcome_fill(point.outcome), claim_words(point, theory), claim_mark(point)};
  });
  return out + map_outcomes_legend(results, h, g.backend) + marks_legend(h + 64.0, verdict) +
         "</svg>\n";
}

}  // namespace bb
