// A table of text cells, rendered as Markdown or as aligned terminal text.
#pragma once

#include <string>
#include <vector>

namespace bb {

struct Table {
  std::vector<std::string> headers;
  std::vector<std::vector<std::string>> rows;
  /// Columns whose cells line up to the right (numbers).
  std::vector<bool> right_aligned;
};

/// Every header and cell goes through markdown_text: no text breaks a row or adds HTML.
std::string render_markdown(const Table& table);
std::string render_text(const Table& table);

}  // namespace bb
