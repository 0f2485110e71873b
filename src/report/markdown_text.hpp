// Text from a case file or a backend, made safe to put into a Markdown page: it cannot
// break a table row, start a new line or inject HTML, whatever it holds.
#pragma once

#include <string>

namespace bb {

/// `text` as one line of Markdown: '|' becomes "\|", '$' "\$" and '\' "\\", each line break (LF, CR
/// or CRLF) one space, and '<', '>', '&' the entities "&lt;", "&gt;", "&amp;". Used for every table
/// cell and for every heading or line built from a case's or a backend's text.
std::string markdown_text(const std::string& text);

}  // namespace bb
