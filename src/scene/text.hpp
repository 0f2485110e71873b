// Small text helpers for messages.
#pragma once

#include <string>
#include <vector>

namespace bb {

/// "a, b, c".
inline std::string joined(const std::vector<std::string>& words) {
  std::string out;
  for (const std::string& w : words) out += (out.empty() ? "" : ", ") + w;
  return out;
}

}  // namespace bb
