// Typed, line-aware access to one TOML table of a case file. Every key read is
// remembered, so finish() can reject the keys nobody asked for.
#pragma once

#include <toml++/toml.h>

#include <optional>
#include <set>
#include <string>
#include <vector>

#include "model/vec3.hpp"
#include "study/case_error.hpp"

namespace bb {

class TomlReader {
 public:
  /// Told of every key the loader asks any reader for, with the table it belongs to as the
  /// reader was first named ("the case", "[air]", "[[body]]", "[engines.ode]"): the keys a
  /// case file may hold, for the documentation's coverage test. Null (the default): off.
  using KeyObserver = void (*)(const std::string& table, const std::string& key);
  static void observe_keys(KeyObserver observer);

  /// `where` names the table in messages, e.g. "[air]" or "[[body]] 'ball'".
  TomlReader(const toml::table& table, std::string file, std::string where, int line);

  double number(const std::string& key);
  double number_or(const std::string& key, double fallback);
  int integer(const std::string& key);
  int integer_or(const std::string& key, int fallback);
  bool boolean_or(const std::string& key, bool fallback);
  std::string string(const std::string& key);
  std::string string_or(const std::string& key, const std::string& fallback);
  Vec3 vec3(const std::string& key);
  Vec3 vec3_or(const std::string& key, const Vec3& fallback);
  std::vector<double> numbers(const std::string& key, std::size_t count = 0);
  std::vector<std::string> strings(const std::string& key);
  std::vector<std::string> strings_or(const std::string& key, std::vector<std::string> fallback);
  /// A sub-table ([air]); nullptr when absent.
  const toml::table* table(const std::string& key);
  /// An array of tables ([[body]]); empty when absent.
  std::vector<const toml::table*> tables(const std::string& key);

  bool has(const std::string& key) const { return table_.contains(key); }
  /// Whether `key` holds a number (an integer or a float).
  bool holds_number(const std::string& key) const {
    const toml::node* n = table_.get(key);
    return n != nullptr && (n->is_integer() || n->is_floating_point());
  }
  /// Line of a key's value, or of the table when the key is absent.
  int line_of(const std::string& key) const;
  int line() const { return line_; }
  const std::string& file() const { return file_; }
  const std::string& where() const { return where_; }
  /// Name the table differently in later messages (once its name key is known).
  void rename(std::string where) { where_ = std::move(where); }
  [[noreturn]] void fail(int line, const std::string& problem) const;
  /// Reject every key that was never read.
  void finish() const;

 private:
  const toml::node* find(const std::string& key);
  const toml::node& require(const std::string& key);
  double as_number(const std::string& key, const toml::node& node) const;
  /// A string node's value; fails when it holds a control character.
  std::string text(const std::string& key, const toml::node& node) const;

  const toml::table& table_;
  std::string file_;
  std::string where_;
  std::string table_name_;  ///< `where` as first given, for the key observer
  int line_;
  std::set<std::string> read_;
};

/// Line of a node in its file (1-based), or `fallback` when toml++ has none.
int node_line(const toml::node& node, int fallback);

}  // namespace bb
