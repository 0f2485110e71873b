// Where a backend's outcome on a map differs from the reference's at the same point: the
// outcomes as the map's cells classify them (map_cells.hpp), compared category by category.
// A point where the reference has no outcome (it is unsupported there, failed or was not
// run) is said to be one, never counted as the same.
#pragma once

#include <string>

#include "run/results.hpp"

namespace bb {

enum class MapDifference { Same, Differs, NoReference, NotRun };

/// The difference's name, as the legend and the page say it.
std::string map_difference_name(MapDifference difference);

/// `backend`'s outcome at `point` against the reference's there: NotRun when the backend has
/// no row at the point, NoReference when the reference's outcome is not one it can be
/// compared with (unsupported, failed, no row), else Same or Differs.
MapDifference map_difference(const Scene& scene, const SweepPoint& point,
                             const std::string& backend);

/// The words a cell's tooltip gives: "differs: past the onset here, the reference ok".
std::string map_difference_words(const Scene& scene, const SweepPoint& point,
                                 const std::string& backend);

/// The file of the differences' small multiples: "<case>-map-differs.svg".
std::string map_differences_file(const Scene& scene);

/// The page's paragraph and table on the differences (per backend but the reference, how
/// many points differ, are the same and have no reference outcome), under `file`'s picture.
std::string map_differences_markdown(const CaseResults& results, const std::string& file);

}  // namespace bb
