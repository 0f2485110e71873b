// What acts on a scene's bodies beyond gravity, air and contact, each kind with every number
// that changes the physics: the springs, the spring grid, the wave surface, the hinges, the
// impulses and the constant pushes, so a reader can redo the computation by hand.
#pragma once

#include <string>

#include "study/scene.hpp"

namespace bb {

/// Markdown: a line for the grid and the waves, a table per other kind present; empty when
/// the scene has none of them.
std::string describe_interactions(const Scene& scene);

/// Whether body `index` was made by the [grid] or the [waves] rather than written as a
/// [[body]] (the page folds those away).
bool generated_body(const Scene& scene, int index);

}  // namespace bb
