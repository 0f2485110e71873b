// The engine settings a case may give under [engines.<engine>], with their defaults, as
// the engines' own descriptions (engine_catalogue.hpp) declare them. One table serves the
// loader (to reject unknown keys) and the adapters (for defaults).
#pragma once

#include <string>
#include <vector>

#include "seam/backend.hpp"
#include "seam/engine_catalogue.hpp"
#include "seam/engine_tables.hpp"

namespace bb {

/// The key of `engine`'s table, or nullptr when unknown.
const EngineKey* find_engine_key(const EngineDescription& engine, const std::string& key);

/// The case's value for `engine`.`key`, or the default its description gives.
double engine_setting(const EngineTables& tables, const EngineDescription& engine,
                      const std::string& key);

/// Every key of `engine` with the value this case gives it, for a run's engine_settings.
Settings engine_key_settings(const EngineTables& tables, const EngineDescription& engine);

}  // namespace bb
