// Results as JSON, schema "beachball-results/1" (docs/design.md, a contract).
#pragma once

#include <nlohmann/json.hpp>

#include "run/results.hpp"

namespace bb {

nlohmann::ordered_json results_json(const CaseResults& results);

}  // namespace bb
