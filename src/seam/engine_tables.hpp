// The engines' settings as a case gives them ([engines.<engine>]): the study reads them, and
// each backend is told them (BackendSettings, seam/backend.hpp) and reads its own.
#pragma once

#include <map>
#include <string>

namespace bb {

/// A case's value for one engine setting; see engine_keys.hpp for the keys.
struct EngineValue {
  double value = 0.0;
  int line = 0;
};

/// Per engine ([engines.<engine>]), the values a case sets, by key.
using EngineTables = std::map<std::string, std::map<std::string, EngineValue>>;

}  // namespace bb
