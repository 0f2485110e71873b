// The engines this build of beachball knows, built or not, and the plugins from outside: the
// adapters' descriptions, gathered by adapters/CMakeLists.txt into a generated file of this
// library. The loader is handed the catalogue (run/case_loading.cpp); the model compiles no
// adapter's code.
#pragma once

#include "seam/engine_catalogue.hpp"

namespace bb {

/// Every engine the adapters describe, in the adapters' CMake order.
const EngineCatalogue& built_in_engine_catalogue();

/// The built-in engines, then one engine per plugin from outside the tree (outside_plugins.hpp).
const EngineCatalogue& engine_catalogue();

}  // namespace bb
