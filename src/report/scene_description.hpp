// The scene in words and a table, from its case file.
#pragma once

#include <string>

#include "study/scene.hpp"

namespace bb {

/// Markdown: timing, gravity, air, and a table of the bodies.
std::string describe_scene(const Scene& scene);

}  // namespace bb
