// A guard in front of the TOML parser: toml++ recurses once per part of a dotted key or
// table header and once per level of nested arrays and inline tables, so a 70 KB file of
// 35,000 key parts overflows the stack. The guard scans the text first (strings and
// comments skipped) and refuses anything deeper than any real case needs.
#pragma once

#include <string>
#include <string_view>

namespace bb {

/// Most parts a dotted key or table header may have ("a.b.c" has 3).
inline constexpr int kMaxKeyParts = 64;
/// Deepest nesting of arrays and inline tables in a value.
inline constexpr int kMaxValueNesting = 64;

/// Throws CaseError naming `file` and the line when `text` has a key with more than
/// kMaxKeyParts parts or a value nested deeper than kMaxValueNesting.
void check_toml_depth(std::string_view text, const std::string& file);

}  // namespace bb
