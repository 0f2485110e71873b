// The plots of where the moving bodies go (trajectory.svg) and how fast (speed.svg): one
// panel per group of bodies, every backend over the reference.
#pragma once

#include <string>

#include "files/file_batch.hpp"
#include "run/case_runner.hpp"

namespace bb {

/// One panel per group of bodies (body_panels.hpp), every backend over the reference. With
/// `speed`, each body's speed against time; else its path y against x where the group moves
/// both ways in the plane, or the coordinate that moves most against time. Bodies sharing a
/// panel are named at the end of the reference's curve. A run far off the reference's scale
/// is cut at the axis and named above the panels; the legend has a band of its own. Returns
/// the file's name, or "" when there is nothing to draw.
std::string bodies_plot(const CaseResults& results, FileBatch& batch, const std::string& name,
                        bool speed);

}  // namespace bb
