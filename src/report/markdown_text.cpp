#include "report/markdown_text.hpp"

namespace bb {

std::string markdown_text(const std::string& text) {
  std::string out;
  out.reserve(text.size());
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    switch (c) {
      // A backslash is doubled, so one in the text cannot unescape the '|' after it.
      case '\\':
        out += "\\\\";
        break;
      case '|':
        out += "\\|";
        break;
      // A '$' would open a math span on GitHub (and take the text's backslashes literally).
      case '$':
        out += "\\$";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '&':
        out += "&amp;";
        break;
      case '\r':
        // CRLF is one line break, so one space.
        if (i + 1 < text.size() && text[i + 1] == '\n') ++i;
        out += ' ';
        break;
      case '\n':
        out += ' ';
        break;
      default:
        out += c;
    }
  }
  return out;
}

}  // namespace bb
