#include "study/control_characters.hpp"

#include <algorithm>
#include <cstdio>

#include "study/case_error.hpp"

namespace bb {

namespace {

struct Found {
  std::size_t at;
  unsigned code;
};

std::optional<Found> find_control(std::string_view text, std::string_view allowed) {
  for (std::size_t i = 0; i < text.size(); ++i) {
    const auto c = static_cast<unsigned char>(text[i]);
    if ((c < 0x20 && allowed.find(static_cast<char>(c)) == std::string_view::npos) || c == 0x7F)
      return Found{i, c};
    // C1 controls are U+0080 to U+009F, in UTF-8 the bytes C2 80 to C2 9F.
    if (c == 0xC2 && i + 1 < text.size()) {
      const auto next = static_cast<unsigned char>(text[i + 1]);
      if (next >= 0x80 && next <= 0x9F) return Found{i, next};
    }
  }
  return std::nullopt;
}

std::string code_point(unsigned code) {
  char text[8];
  std::snprintf(text, sizeof text, "U+%04X", code);
  return text;
}

}  // namespace

std::optional<std::string> first_control_character(std::string_view text,
                                                   std::string_view allowed) {
  const auto found = find_control(text, allowed);
  return found ? std::optional<std::string>(code_point(found->code)) : std::nullopt;
}

void refuse_control_characters(std::string_view text, const std::string& file) {
  const auto found = find_control(text, "\t\n\r");
  if (!found) return;
  const auto line = 1 + std::count(text.begin(), text.begin() + found->at, '\n');
  throw CaseError(file, static_cast<int>(line),
                  "the file holds a control character (" + code_point(found->code) +
                      (found->code == 0 ? ", a NUL byte" : "") +
                      "); a case file is text: printable characters, tabs and line breaks");
}

}  // namespace bb
