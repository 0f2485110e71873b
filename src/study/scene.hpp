// A case as loaded from one case file: its World (model/world.hpp) and its Study
// (study/study.hpp).
#pragma once

#include "model/world.hpp"
#include "study/study.hpp"

namespace bb {

/// A case: a World and a Study, as loaded from one case file.
struct Scene : World, Study {};

}  // namespace bb
