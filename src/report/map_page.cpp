#include "report/map_page.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <map>

#include "model/text.hpp"
#include "report/map_cells.hpp"
#include "report/map_difference.hpp"
#include "report/map_picture.hpp"
#include "report/markdown_text.hpp"
#include "report/table.hpp"

namespace bb {

namespace {

const RunRecord* run_in(const SweepPoint& point, const std::string& backend) {
  for (const RunRecord& run : point.runs)
    if (run.backend == backend) return &run;
  return nullptr;
}

/// The outcomes a table column is given to, in the legend's order.
std::vector<MapOutcome> counted_outcomes(const Scene& scene) {
  std::vector<MapOutcome> out = {MapOutcome::Ok};
  if (!scene.sweep->onset.empty()) out.push_back(MapOutcome::PastOnset);
  for (MapOutcome o :
       {MapOutcome::Diverged, MapOutcome::Unsupported, MapOutcome::Failed, MapOutcome::Absent})
    out.push_back(o);
  return out;
}

/// What the page says of a map no theory bounds for any of its backends.
const char* const kNoTheory =
    " No theory bounds either axis of this map for any of its backends: no line is drawn, "
    "and no map's claim (`region = \"theory\"`) can be stated on it.";

/// The first theory drawn on any backend's map, nullptr where none is.
const MapTheory* drawn_theory(const CaseResults& results) {
  for (const std::string& backend : map_backends(results))
    if (const MapTheory* theory = map_theory(*results.scene, backend)) return theory;
  return nullptr;
}

/// Per backend, its points by outcome, and the theory's bounds where there are some.
std::string outcome_table(const CaseResults& results) {
  const Scene& scene = *results.scene;
  const std::vector<MapOutcome> outcomes = counted_outcomes(scene);
  Table t{{"backend"}, {}, {false}};
  for (MapOutcome o : outcomes) {
    t.headers.push_back(map_outcome_name(o));
    t.right_aligned.push_back(true);
  }
  const MapTheory* drawn = drawn_theory(results);
  t.headers.push_back(drawn ? drawn->column : "theory's bound");
  t.right_aligned.push_back(false);
  for (const std::string& backend : map_backends(results)) {
    std::map<MapOutcome, int> count;
    for (const SweepPoint& p : results.sweep->points)
      ++count[map_outcome(scene, run_in(p, backend))];
    std::vector<std::string> row{backend};
    for (MapOutcome o : outcomes) row.push_back(std::to_string(count[o]));
    const std::vector<BoundaryPoint> line = map_boundary(scene, backend);
    const MapTheory* theory = map_theory(scene, backend);
    row.push_back(line.empty() ? "-"
                  : line.front().limit == 0.0
                      ? "none: unstable at every step"
                      : map_bound_text(*theory, line.front().limit) + " to " +
                            map_bound_text(*theory, line.back().limit));
    t.rows.push_back(row);
  }
  return render_markdown(t);
}

/// The smallest and the largest of a [[sweep]]'s values, a step as a frame rate's ("1/60 s").
std::string span_text(const Sweep& sweep) {
  const auto [lo, hi] = std::minmax_element(sweep.values.begin(), sweep.values.end());
  if (sweep.parameter == "dt") return format_dt(*lo) + " s to " + format_dt(*hi) + " s";
  return short_number(*lo) + " to " + short_number(*hi);
}

}  // namespace

std::string map_markdown(const CaseResults& results, const MapFiles& files) {
  if (!results.sweep || results.sweep->second_parameter.empty()) return "";
  const Scene& scene = *results.scene;
  const Sweep& first = *scene.sweep;
  const Sweep& second = *scene.second_sweep;
  std::string out = fmt::format("\n## Map of `{}` by `{}`\n\n", markdown_text(first.parameter),
                                markdown_text(second.parameter));
  if (!first.published.empty())
    out += "**What the published study found.** " + markdown_text(first.published) + "\n\n";
  out += fmt::format(
      "The whole case run again at each of {} x {} points: `{}` from {} (up the side) with `{}` "
      "from {} (along the bottom), every backend at {}. Each cell is a run's outcome at that "
      "point{}.{}\n\n",
      first.values.size(), second.values.size(), markdown_text(first.parameter), span_text(first),
      markdown_text(second.parameter), span_text(second),
      first.parameter == "dt" || second.parameter == "dt"
          ? std::string("the point's step")
          : "report_dt = " + format_dt(scene.report_dt) + " s",
      first.onset.empty()
          ? ""
          : fmt::format("; an ok run whose `{}` exceeds {} is past the onset",
                        markdown_text(first.onset), short_number(first.onset_above)),
      (first.colour.empty()
           ? std::string()
           : fmt::format(" An ok run's cell is coloured instead by its `{}` error (against "
                         "the reference at that point), on one scale for every backend: the "
                         "bar under the maps.",
                         markdown_text(first.colour))) +
          (drawn_theory(results) ? " " + drawn_theory(results)->page : kNoTheory));
  if (!files.multiples.empty()) out += "![every backend's map](" + files.multiples + ")\n\n";
  if (!files.backends.empty()) {
    out += "Each backend's map alone:";
    for (const auto& [backend, file] : files.backends)
      out += fmt::format(" [{}]({})", markdown_text(backend), file);
    out += ".\n\n";
  }
  return out + outcome_table(results) + "\n" + map_differences_markdown(results, files.differs);
}

}  // namespace bb
