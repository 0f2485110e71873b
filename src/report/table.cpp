#include "report/table.hpp"

#include <algorithm>

#include "report/markdown_text.hpp"

namespace bb {

namespace {

/// Characters as shown: UTF-8 continuation bytes do not count.
std::size_t shown_width(const std::string& s) {
  std::size_t n = 0;
  for (unsigned char c : s) n += (c & 0xC0) != 0x80;
  return n;
}

bool right(const Table& t, std::size_t c) {
  return c < t.right_aligned.size() && t.right_aligned[c];
}

std::vector<std::size_t> widths(const Table& t) {
  std::vector<std::size_t> w(t.headers.size(), 0);
  for (std::size_t c = 0; c < t.headers.size(); ++c) w[c] = t.headers[c].size();
  for (const auto& row : t.rows)
    for (std::size_t c = 0; c < row.size() && c < w.size(); ++c)
      w[c] = std::max(w[c], row[c].size());
  return w;
}

std::string pad(const std::string& s, std::size_t width, bool to_right) {
  const std::size_t n = shown_width(s);
  const std::string fill(width > n ? width - n : 0, ' ');
  return to_right ? fill + s : s + fill;
}

/// Every header and cell through markdown_text, so no text can break a row.
Table escaped(const Table& t) {
  Table out = t;
  for (std::string& h : out.headers) h = markdown_text(h);
  for (auto& row : out.rows)
    for (std::string& cell : row) cell = markdown_text(cell);
  return out;
}

}  // namespace

std::string render_markdown(const Table& table) {
  const Table t = escaped(table);
  const auto w = widths(t);
  std::string out = "|";
  for (std::size_t c = 0; c < t.headers.size(); ++c)
    out += " " + pad(t.headers[c], w[c], false) + " |";
  out += "\n|";
  for (std::size_t c = 0; c < t.headers.size(); ++c)
    out += right(t, c) ? " " + std::string(std::max<std::size_t>(w[c], 2) - 1, '-') + ": |"
                       : " " + std::string(std::max<std::size_t>(w[c], 1), '-') + " |";
  out += "\n";
  for (const auto& row : t.rows) {
    out += "|";
    for (std::size_t c = 0; c < t.headers.size(); ++c)
      out += " " + pad(c < row.size() ? row[c] : "", w[c], right(t, c)) + " |";
    out += "\n";
  }
  return out;
}

std::string render_text(const Table& t) {
  const auto w = widths(t);
  std::string out;
  for (std::size_t c = 0; c < t.headers.size(); ++c)
    out += (c ? "  " : "") + pad(t.headers[c], w[c], right(t, c));
  out += "\n";
  for (std::size_t c = 0; c < t.headers.size(); ++c)
    out += (c ? "  " : "") + std::string(w[c], '-');
  out += "\n";
  for (const auto& row : t.rows) {
    for (std::size_t c = 0; c < t.headers.size(); ++c)
      out += (c ? "  " : "") + pad(c < row.size() ? row[c] : "", w[c], right(t, c));
    out += "\n";
  }
  return out;
}

}  // namespace bb
