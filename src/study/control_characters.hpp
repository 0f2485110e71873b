// A case file is text. Control characters (a NUL byte, an escape that moves a terminal's
// cursor, ...) have no place in it: in the file they are refused before the TOML parser
// sees it, and in a string value (where TOML's "\u0000" escapes can put them) when the
// value is read.
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace bb {

/// The first control character in `text` as "U+001B", or nullopt. Control characters are
/// C0 (below U+0020), DEL (U+007F) and C1 (U+0080 to U+009F, as UTF-8); `allowed` lists
/// C0 characters that are not counted (tab and line breaks in a file, say).
std::optional<std::string> first_control_character(std::string_view text,
                                                   std::string_view allowed = "");

/// Throws CaseError naming `file` and the line of the first control character in `text`
/// other than tab, line feed and carriage return.
void refuse_control_characters(std::string_view text, const std::string& file);

}  // namespace bb
