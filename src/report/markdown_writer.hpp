// The Markdown page of one case: the scene, the tables, the settings and versions.
#pragma once

#include <string>

#include "run/results.hpp"

namespace bb {

std::string results_markdown(const CaseResults& results);

}  // namespace bb
