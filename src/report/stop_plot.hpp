// The plot of sliding bodies (seed section 6): for each body whose stop is observed, the
// distance it has slid and its velocity along its direction of sliding against time, at
// report_dt, from a little before the reference's stop to the end, where a crawl shows.
#pragma once

#include <string>
#include <vector>

#include "files/file_batch.hpp"
#include "run/results.hpp"

namespace bb {

/// The plotted bodies (the first kPlottedBodies) that have a stop_time, stop_distance or
/// rest_creep observable, in scene order.
std::vector<int> stopping_bodies(const Scene& scene);

/// Draws the plot as `name` into `batch`; returns why there is none, else "".
std::string stop_plot(const CaseResults& results, FileBatch& batch, const std::string& name);

}  // namespace bb
