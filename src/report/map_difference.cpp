#include "report/map_difference.hpp"

#include <fmt/format.h>

#include <map>

#include "report/map_cells.hpp"
#include "report/map_picture.hpp"
#include "report/table.hpp"
#include "study/backend_names.hpp"

namespace bb {

namespace {

const RunRecord* difference_row(const SweepPoint& point, const std::string& backend) {
  for (const RunRecord& run : point.runs)
    if (run.backend == backend) return &run;
  return nullptr;
}

}  // namespace

std::string map_difference_name(MapDifference difference) {
  switch (difference) {
    case MapDifference::Same:
      return "same as the reference";
    case MapDifference::Differs:
      return "differs from the reference";
    case MapDifference::NoReference:
      return "no reference outcome";
    case MapDifference::NotRun:
      break;
  }
  return "not run";
}

MapDifference map_difference(const Scene& scene, const SweepPoint& point,
                             const std::string& backend) {
  const RunRecord* run = difference_row(point, backend);
  if (run == nullptr) return MapDifference::NotRun;
  const MapOutcome reference = map_outcome(scene, difference_row(point, kReferenceName));
  if (!ran_to_an_outcome(reference)) return MapDifference::NoReference;
  return map_outcome(scene, run) == reference ? MapDifference::Same : MapDifference::Differs;
}

std::string map_difference_words(const Scene& scene, const SweepPoint& point,
                                 const std::string& backend) {
  const std::string own = map_outcome_name(map_outcome(scene, difference_row(point, backend)));
  const std::string reference =
      map_outcome_name(map_outcome(scene, difference_row(point, kReferenceName)));
  switch (map_difference(scene, point, backend)) {
    case MapDifference::Same:
      return "same as the reference: " + own;
    case MapDifference::Differs:
      return "differs: " + own + " here, the reference " + reference;
    case MapDifference::NoReference:
      return "no reference outcome (the reference: " + reference + "); " + own + " here";
    case MapDifference::NotRun:
      break;
  }
  return "not run";
}

std::string map_differences_file(const Scene& scene) {
  return scene.name + "-map-differs.svg";
}

std::string map_differences_markdown(const CaseResults& results, const std::string& file) {
  const Scene& scene = *results.scene;
  const std::vector<MapDifference> shown = {MapDifference::Differs, MapDifference::Same,
                                            MapDifference::NoReference, MapDifference::NotRun};
  Table t{{"backend"}, {}, {false}};
  for (MapDifference d : shown) {
    t.headers.push_back(map_difference_name(d));
    t.right_aligned.push_back(true);
  }
  for (const std::string& backend : map_backends(results)) {
    if (backend == kReferenceName) continue;
    std::map<MapDifference, int> count;
    for (const SweepPoint& p : results.sweep->points) ++count[map_difference(scene, p, backend)];
    std::vector<std::string> row{backend};
    for (MapDifference d : shown) row.push_back(std::to_string(count[d]));
    t.rows.push_back(row);
  }
  std::string out =
      "**Where each backend differs from the reference.** Each cell compares the backend's "
      "outcome at a point with the reference's at the same point, category by category (ok, "
      "past the onset, diverged, unsupported, failed): dark where they differ, pale where they "
      "are the same, and a question mark where the reference has no outcome to compare with "
      "(it is unsupported there, failed or was not run), which is never counted as the same.\n\n";
  if (!file.empty()) out += "![where each backend differs from the reference](" + file + ")\n\n";
  return out + render_markdown(t);
}

}  // namespace bb
