// Results rows compared as text: what two runs of the same case must agree on.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

namespace bb::test {

/// A results row as the JSON writes it, without its cost (timing differs from run to run).
inline std::string row_text(nlohmann::ordered_json row) {
  row.erase("cost");
  return row.dump();
}

}  // namespace bb::test
