// Reading the reference tables of docs/: the heading each table stands under and the first
// column of its rows, so that tests can hold the docs to what the code accepts. A table is
// a run of lines starting with '|'; its header is the first cell of its first line; a row's
// name is the text of the first `code span` in its first cell. Fenced code is skipped.
#pragma once

#include <string>
#include <vector>

#include "support/test_support.hpp"

namespace bb::test {

struct DocRow {
  std::string name;  ///< the first code span of the first cell ("" when it has none)
  int line = 0;
};

struct DocTable {
  std::string heading;  ///< the text of the heading above it, without the #s
  std::string header;   ///< the first cell of its header row, trimmed
  int line = 0;
  std::vector<DocRow> rows;
};

struct DocHeading {
  std::string text;
  int line = 0;
};

struct DocFile {
  std::vector<DocHeading> headings;
  std::vector<DocTable> tables;
};

inline std::string trimmed(const std::string& s) {
  const auto first = s.find_first_not_of(" \t");
  if (first == std::string::npos) return "";
  return s.substr(first, s.find_last_not_of(" \t") + 1 - first);
}

/// The text between the first pair of backticks in `s`, or "".
inline std::string first_code_span(const std::string& s) {
  const auto open = s.find('`');
  if (open == std::string::npos) return "";
  const auto close = s.find('`', open + 1);
  if (close == std::string::npos) return "";
  return s.substr(open + 1, close - open - 1);
}

/// The first cell of a table line "| a | b |": "a", trimmed (an escaped \| stays in it).
inline std::string first_cell(const std::string& line) {
  std::size_t end = 1;
  while (end < line.size() && !(line[end] == '|' && line[end - 1] != '\\')) ++end;
  return trimmed(line.substr(1, end - 1));
}

inline DocFile read_doc(const std::string& text) {
  DocFile doc;
  std::string heading;
  bool in_fence = false;
  bool in_table = false;
  bool header_seen = false;
  int number = 0;
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t end = std::min(text.find('\n', start), text.size());
    const std::string line = text.substr(start, end - start);
    start = end + 1;
    ++number;
    if (line.rfind("```", 0) == 0) in_fence = !in_fence;
    if (in_fence) continue;
    if (line.rfind("#", 0) == 0) {
      heading = trimmed(line.substr(line.find_first_not_of('#')));
      doc.headings.push_back({heading, number});
      in_table = false;
      continue;
    }
    if (line.rfind("|", 0) != 0) {
      in_table = false;
      continue;
    }
    if (!in_table) {
      doc.tables.push_back({heading, first_cell(line), number, {}});
      in_table = true;
      header_seen = false;
      continue;
    }
    // The separator row under the header.
    if (!header_seen) {
      header_seen = true;
      continue;
    }
    doc.tables.back().rows.push_back({first_code_span(first_cell(line)), number});
  }
  return doc;
}

inline DocFile read_doc_file(const std::string& relative) {
  return read_doc(bytes(source_path(relative)));
}

}  // namespace bb::test
