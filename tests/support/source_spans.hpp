// The sizes the project holds its C++ to (tests/docs/size_limits_test.cpp): a file's lines and
// each function's. What counts as a function: a brace opened where declarations stand (at file
// scope, or inside a namespace, an extern "C" block, a class, struct or union, at any
// nesting) after a head that has a parameter list's `)` and no initializer's `=`: free
// functions, member functions defined in their class, constructors (braces of a member
// initializer belong to the head), operators, and TEST/TEST_F/TEST_P bodies. Its lines run
// from the first line of its head (attributes, template line and access label excluded) to
// its closing brace, both counted. Not functions: namespaces, classes, structs, unions and
// enums (their braces hold declarations or enumerators), and initializers (`= {`, `T x{`,
// and a lambda bound to a name at file scope, which is an initializer too). Comments, string,
// character and raw string literals and preprocessor lines are blanked first, so a brace
// inside them counts for nothing; a lambda or a local class inside a function is part of it.
#pragma once

#include <algorithm>
#include <cctype>
#include <string>
#include <vector>

namespace bb::test {

/// One function found: its name as its head gives it, its first line and its length.
struct FunctionSpan {
  std::string name;
  int first_line = 0;
  int lines = 0;
};

/// The lines of a text: its newlines, and one more if the last line has none.
inline int line_count(const std::string& text) {
  int lines = 0;
  for (char c : text) lines += c == '\n';
  return lines + (!text.empty() && text.back() != '\n');
}

/// A letter, a digit or an underscore: part of a name or a number.
inline bool is_identifier_char(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
}

/// The text with comments and the insides of literals replaced by spaces (newlines kept, so
/// lines and columns stay where they were).
inline std::string code_without_literals(const std::string& text) {
  std::string out = text;
  const auto blank = [&](std::size_t from, std::size_t to) {
    for (std::size_t i = from; i < to && i < out.size(); ++i)
      if (out[i] != '\n') out[i] = ' ';
  };
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    const char next = i + 1 < text.size() ? text[i + 1] : '\0';
    if (c == '/' && next == '/') {
      const std::size_t end = text.find('\n', i);
      blank(i, end);
      i = end == std::string::npos ? text.size() : end;
    } else if (c == '/' && next == '*') {
      const std::size_t end = std::min(text.find("*/", i + 2), text.size() - 2) + 2;
      blank(i, end);
      i = end - 1;
    } else if (c == '"' && i > 0 && text[i - 1] == 'R' &&
               (i < 2 || !is_identifier_char(text[i - 2]) || text[i - 2] == '8' ||
                text[i - 2] == 'u' || text[i - 2] == 'U' || text[i - 2] == 'L')) {
      // A raw string: R"delimiter( ... )delimiter"
      const std::size_t open = text.find('(', i);
      const std::string close = ")" + text.substr(i + 1, open - i - 1) + "\"";
      const std::size_t end = std::min(text.find(close, open), text.size() - close.size());
      blank(i + 1, end + close.size() - 1);
      i = end + close.size() - 1;
    } else if (c == '"' || (c == '\'' && (i == 0 || !is_identifier_char(text[i - 1])))) {
      // A string or character literal (a quote after a digit separates digits).
      std::size_t end = i + 1;
      while (end < text.size() && text[end] != c && text[end] != '\n')
        end += text[end] == '\\' ? 2 : 1;
      blank(i + 1, end);
      i = end;
    }
  }
  return out;
}

/// The text with preprocessor lines (and their continuations) blanked too.
inline std::string code_only(const std::string& text) {
  std::string out = code_without_literals(text);
  bool continued = false;
  for (std::size_t start = 0; start < out.size();) {
    std::size_t end = out.find('\n', start);
    if (end == std::string::npos) end = out.size();
    const std::size_t first = out.find_first_not_of(" \t", start);
    const bool directive = continued || (first < end && out[first] == '#');
    continued = directive && end > start && text[end - 1] == '\\';
    if (directive)
      for (std::size_t i = start; i < end; ++i) out[i] = ' ';
    start = end + 1;
  }
  return out;
}

/// Text of `head` at parenthesis depth 0, others blanked: where a head's own `=`, `:` and
/// `)` are told from those of its parameters.
inline std::string top_level(const std::string& head) {
  std::string out = head;
  int depth = 0;
  for (char& c : out) {
    if (c == '(') ++depth;
    if (depth > 0 && c != '(' && c != ')') c = ' ';
    if (c == ')') --depth;
  }
  return out;
}

/// The name a text begins with (empty where it begins with anything else).
inline std::string first_word(const std::string& text) {
  std::size_t end = 0;
  while (end < text.size() && is_identifier_char(text[end])) ++end;
  return text.substr(0, end);
}

/// `head` without leading spaces, `template <...>` and `[[attributes]]` (once they close).
inline std::string without_prefixes(std::string head) {
  for (;;) {
    head.erase(0, head.find_first_not_of(" \t\n"));
    const bool attribute = head.rfind("[[", 0) == 0;
    if (!attribute && first_word(head) != "template") return head;
    const char open = attribute ? '[' : '<', close = attribute ? ']' : '>';
    int depth = 0;
    std::size_t end = head.find(open);
    for (; end < head.size(); ++end) {
      depth += head[end] == open ? 1 : head[end] == close ? -1 : 0;
      if (depth == 0) break;
    }
    if (end >= head.size()) return "";  // not closed yet: nothing of the head proper
    head.erase(0, end + 1);
  }
}

/// Whether a head assigns: a lone `=` of its own (not `==`, `<=`, `operator=`, a default).
inline bool has_initializer(const std::string& head) {
  const std::string own = top_level(head);
  for (std::size_t i = own.find('='); i != std::string::npos; i = own.find('=', i + 1)) {
    const char before = i > 0 ? own[i - 1] : ' ', after = i + 1 < own.size() ? own[i + 1] : ' ';
    if (std::string("=!<>+-*/%&|^").find(before) != std::string::npos || after == '=') continue;
    const std::size_t word_end = own.find_last_not_of(" \t\n", i - 1);
    if (word_end != std::string::npos && word_end >= 7 &&
        own.compare(word_end - 7, 8, "operator") == 0)
      continue;
    return true;
  }
  return false;
}

/// Whether a head has reached a constructor's member initializers (`Foo(int a) : a_`).
inline bool in_member_initializers(const std::string& head) {
  const std::string own = top_level(head);
  const std::size_t parameters_end = own.find(')');
  if (parameters_end == std::string::npos) return false;
  for (std::size_t i = own.find(':', parameters_end); i != std::string::npos;
       i = own.find(':', i + 1)) {
    const bool scope_operator = (i + 1 < own.size() && own[i + 1] == ':') || own[i - 1] == ':';
    if (!scope_operator) return true;
  }
  return false;
}

/// Whether a brace after `head` opens a member's brace initializer (`Foo(int a) : a_{a}`):
/// in a constructor's initializers, right after a member's name (or a template's `>`).
inline bool member_initializer(const std::string& head) {
  const std::size_t last = head.find_last_not_of(' ');
  return last != std::string::npos && (is_identifier_char(head[last]) || head[last] == '>') &&
         in_member_initializers(head);
}

/// What a brace opens, told from the head before it.
enum class Opens { kDeclarations, kFunction, kOther };

inline Opens classify(const std::string& raw_head) {
  const std::string head = without_prefixes(raw_head);
  const std::string word = first_word(head);
  const bool has_parameters = top_level(head).find(')') != std::string::npos;
  if (word == "namespace" || (word == "inline" && head.find("namespace") != std::string::npos))
    return Opens::kDeclarations;
  if ((word == "extern" || word == "class" || word == "struct" || word == "union") &&
      !has_parameters)
    return Opens::kDeclarations;
  if (word == "enum" || has_initializer(head) || !has_parameters) return Opens::kOther;
  return Opens::kFunction;
}

/// A function's name for a message: the word before its parameters, or the whole macro
/// call for a TEST body.
inline std::string function_name(const std::string& raw_head) {
  const std::string head = without_prefixes(raw_head);
  // An operator's name runs to its parameters: past its own `()` for operator().
  const std::size_t op = head.find("operator");
  const std::size_t open = op == std::string::npos              ? head.find('(')
                           : head.compare(op + 8, 2, "()") == 0 ? head.find('(', op + 10)
                                                                : head.find('(', op);
  std::size_t start = op == std::string::npos ? open : op;
  while (start > 0 &&
         (is_identifier_char(head[start - 1]) || head[start - 1] == ':' || head[start - 1] == '~'))
    --start;
  const std::string name = head.substr(start, open - start);
  if (name.rfind("TEST", 0) == 0 || name.rfind("TYPED_TEST", 0) == 0)
    return head.substr(start, head.find(')', open) + 1 - start);
  return name;
}

/// Every function of a C++ text (see the top of this file), in order of their closing brace.
inline std::vector<FunctionSpan> function_spans(const std::string& text) {
  const std::string code = code_only(text);
  struct Scope {
    Opens opens;
    int first_line;
    std::string name;
  };
  std::vector<Scope> scopes{{Opens::kDeclarations, 1, ""}};
  std::vector<FunctionSpan> out;
  std::string head;        // the declaration read so far where declarations stand
  std::vector<int> lines;  // the line of each character of `head`
  int line = 1, initializer_braces = 0, open_parentheses = 0;
  for (char c : code) {
    line += c == '\n';
    if (scopes.back().opens != Opens::kDeclarations) {
      // Inside a function or an initializer only the braces count.
      if (c == '{') scopes.push_back({Opens::kOther, line, ""});
      if (c != '}') continue;
      const Scope closed = scopes.back();
      scopes.pop_back();
      if (closed.opens == Opens::kFunction)
        out.push_back({closed.name, closed.first_line, line - closed.first_line + 1});
      continue;
    }
    if (c == '{' && initializer_braces == 0 && open_parentheses == 0 && !member_initializer(head)) {
      const Opens opens = classify(head);
      const std::size_t start = head.size() - without_prefixes(head).size();
      scopes.push_back({opens, start < lines.size() ? lines[start] : line,
                        opens == Opens::kFunction ? function_name(head) : ""});
      head.clear();
      lines.clear();
      open_parentheses = 0;
      continue;
    }
    if ((c == '}' && initializer_braces == 0) || c == ';') {
      if (c == '}' && scopes.size() > 1) scopes.pop_back();
      head.clear();
      lines.clear();
      open_parentheses = 0;
      continue;
    }
    // A default argument's braces, or a member's brace initializer (`Foo(int a) : a_{a} {`)
    // are still the head.
    initializer_braces += c == '{' ? 1 : c == '}' ? -1 : 0;
    open_parentheses += c == '(' ? 1 : c == ')' ? -1 : 0;
    // One space stands for a run of them (a blanked literal can be hundreds of lines).
    if (std::isspace(static_cast<unsigned char>(c)) && !head.empty() && head.back() == ' ')
      continue;
    head += std::isspace(static_cast<unsigned char>(c)) ? ' ' : c;
    lines.push_back(line);
    // An access label is not where a head starts.
    const std::string own = c == ':' ? without_prefixes(head) : "";
    if (own == "public:" || own == "private:" || own == "protected:") {
      head.clear();
      lines.clear();
    }
  }
  return out;
}

}  // namespace bb::test
