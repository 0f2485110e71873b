#include "study/toml_depth.hpp"

#include <vector>

#include "study/case_error.hpp"

namespace bb {

namespace {

/// Where the scanner is in the TOML grammar, as far as recursion is concerned.
enum class Context { Key, Header, Value };

class DepthScanner {
 public:
  DepthScanner(std::string_view text, const std::string& file) : text_(text), file_(file) {}

  void run() {
    while (at_ < text_.size()) {
      const char c = text_[at_];
      if (c == '\n') {
        ++line_;
        // A new line outside any array or inline table starts a new key.
        if (open_.empty()) begin(Context::Key);
        ++at_;
      } else if (c == '#') {
        skip_to_line_end();
      } else if (c == '"' || c == '\'') {
        skip_string(c);
      } else {
        structure(c);
        ++at_;
      }
    }
  }

 private:
  void begin(Context context) {
    context_ = context;
    parts_ = 1;
  }

  void structure(char c) {
    switch (context_) {
      case Context::Key:
        if (c == '=') {
          context_ = Context::Value;
        } else if (c == '[' && open_.empty()) {
          begin(Context::Header);
        } else if (c == '.') {
          add_part();
        } else if (c == '}' && !open_.empty()) {
          close();  // an empty inline table, or a trailing brace
        }
        break;
      case Context::Header:
        if (c == '.') add_part();
        if (c == ']') context_ = Context::Key;
        break;
      case Context::Value:
        if (c == '[' || c == '{') {
          open_.push_back(c);
          if (static_cast<int>(open_.size()) > kMaxValueNesting)
            fail("arrays and inline tables nested more than " + std::to_string(kMaxValueNesting) +
                 " deep");
          if (c == '{') begin(Context::Key);
        } else if (c == ']' || c == '}') {
          close();
        } else if (c == ',' && !open_.empty() && open_.back() == '{') {
          begin(Context::Key);
        }
        break;
    }
  }

  void close() {
    if (!open_.empty()) open_.pop_back();
    context_ = Context::Value;
  }

  void add_part() {
    if (++parts_ > kMaxKeyParts)
      fail("a key or table header with more than " + std::to_string(kMaxKeyParts) +
           " dotted parts");
  }

  void skip_to_line_end() {
    while (at_ < text_.size() && text_[at_] != '\n') ++at_;
  }

  /// Skips a basic or literal string, single- or multi-line, counting its lines.
  void skip_string(char quote) {
    const bool multi = text_.substr(at_, 3) == std::string(3, quote);
    at_ += multi ? 3 : 1;
    while (at_ < text_.size()) {
      const char c = text_[at_];
      if (c == '\\' && quote == '"') {
        at_ += 2;
        continue;
      }
      if (c == '\n') {
        ++line_;
        // An unterminated single-line string ends here; the parser will say so.
        if (!multi) return;
      }
      if (c == quote && (!multi || text_.substr(at_, 3) == std::string(3, quote))) {
        at_ += multi ? 3 : 1;
        return;
      }
      ++at_;
    }
  }

  [[noreturn]] void fail(const std::string& what) const {
    throw CaseError(file_, line_, "the case file has " + what + "; no case needs that many");
  }

  std::string_view text_;
  const std::string& file_;
  std::size_t at_ = 0;
  int line_ = 1;
  Context context_ = Context::Key;
  int parts_ = 1;
  std::vector<char> open_;  ///< the arrays and inline tables open at this point
};

}  // namespace

void check_toml_depth(std::string_view text, const std::string& file) {
  DepthScanner(text, file).run();
}

}  // namespace bb
