#include "study/toml_reader.hpp"

#include <cmath>
#include <sstream>

#include "study/control_characters.hpp"

namespace bb {

namespace {

std::string type_word(const toml::node& node) {
  switch (node.type()) {
    case toml::node_type::string:
      return "a string";
    case toml::node_type::integer:
      return "an integer";
    case toml::node_type::floating_point:
      return "a number";
    case toml::node_type::boolean:
      return "true or false";
    case toml::node_type::array:
      return "a list";
    case toml::node_type::table:
      return "a table";
    default:
      return "a date or time";
  }
}

std::string quoted(const std::string& key) {
  return "'" + key + "'";
}

TomlReader::KeyObserver key_observer = nullptr;

}  // namespace

void TomlReader::observe_keys(KeyObserver observer) {
  key_observer = observer;
}

int node_line(const toml::node& node, int fallback) {
  const auto line = static_cast<int>(node.source().begin.line);
  return line > 0 ? line : fallback;
}

TomlReader::TomlReader(const toml::table& table, std::string file, std::string where, int line)
    : table_(table),
      file_(std::move(file)),
      where_(std::move(where)),
      table_name_(where_),
      line_(line) {}

void TomlReader::fail(int line, const std::string& problem) const {
  throw CaseError(file_, line, problem);
}

const toml::node* TomlReader::find(const std::string& key) {
  read_.insert(key);
  if (key_observer != nullptr) key_observer(table_name_, key);
  return table_.get(key);
}

const toml::node& TomlReader::require(const std::string& key) {
  const toml::node* node = find(key);
  if (node == nullptr) fail(line_, where_ + " needs the key " + quoted(key));
  return *node;
}

int TomlReader::line_of(const std::string& key) const {
  const toml::node* node = table_.get(key);
  return node ? node_line(*node, line_) : line_;
}

double TomlReader::as_number(const std::string& key, const toml::node& node) const {
  double value = 0.0;
  if (const auto* i = node.as_integer())
    value = static_cast<double>(i->get());
  else if (const auto* f = node.as_floating_point())
    value = f->get();
  else
    fail(node_line(node, line_), quoted(key) + " must be a number, not " + type_word(node));
  if (!std::isfinite(value))
    fail(node_line(node, line_), quoted(key) + " must be a finite number (nan and inf are not)");
  return value;
}

double TomlReader::number(const std::string& key) {
  return as_number(key, require(key));
}

double TomlReader::number_or(const std::string& key, double fallback) {
  const toml::node* node = find(key);
  return node ? as_number(key, *node) : fallback;
}

int TomlReader::integer(const std::string& key) {
  const toml::node& node = require(key);
  const auto* i = node.as_integer();
  if (i == nullptr)
    fail(node_line(node, line_), quoted(key) + " must be a whole number, not " + type_word(node));
  if (i->get() < -1000000000 || i->get() > 1000000000)
    fail(node_line(node, line_), quoted(key) + " is out of range");
  return static_cast<int>(i->get());
}

// The *_or readers ask through find() also for an absent key: it is remembered as read and
// the key observer hears of it, so a key left to its default is still one the case may hold.
int TomlReader::integer_or(const std::string& key, int fallback) {
  return table_.contains(key) ? integer(key) : (find(key), fallback);
}

bool TomlReader::boolean_or(const std::string& key, bool fallback) {
  const toml::node* node = find(key);
  if (node == nullptr) return fallback;
  const auto* b = node->as_boolean();
  if (b == nullptr)
    fail(node_line(*node, line_), quoted(key) + " must be true or false, not " + type_word(*node));
  return b->get();
}

std::string TomlReader::text(const std::string& key, const toml::node& node) const {
  const std::string& value = node.as_string()->get();
  // TOML's escapes ("\u001b") can put into a string what the file itself may not hold.
  if (const auto control = first_control_character(value))
    fail(node_line(node, line_), quoted(key) + " holds a control character (" + *control +
                                     "); text in a case is one line of printable characters");
  return value;
}

std::string TomlReader::string(const std::string& key) {
  const toml::node& node = require(key);
  if (!node.is_string())
    fail(node_line(node, line_), quoted(key) + " must be a string, not " + type_word(node));
  return text(key, node);
}

std::string TomlReader::string_or(const std::string& key, const std::string& fallback) {
  return table_.contains(key) ? string(key) : (find(key), fallback);
}

std::vector<double> TomlReader::numbers(const std::string& key, std::size_t count) {
  const toml::node& node = require(key);
  const auto* array = node.as_array();
  if (array == nullptr)
    fail(node_line(node, line_),
         quoted(key) + " must be a list of numbers, not " + type_word(node));
  if (count > 0 && array->size() != count) {
    std::ostringstream s;
    s << quoted(key) << " must have " << count << " numbers, not " << array->size();
    fail(node_line(node, line_), s.str());
  }
  if (array->empty()) fail(node_line(node, line_), quoted(key) + " must not be empty");
  std::vector<double> out;
  for (const toml::node& element : *array) out.push_back(as_number(key, element));
  return out;
}

Vec3 TomlReader::vec3(const std::string& key) {
  const std::vector<double> v = numbers(key, 3);
  return {v[0], v[1], v[2]};
}

Vec3 TomlReader::vec3_or(const std::string& key, const Vec3& fallback) {
  return table_.contains(key) ? vec3(key) : (find(key), fallback);
}

std::vector<std::string> TomlReader::strings(const std::string& key) {
  const toml::node& node = require(key);
  const auto* array = node.as_array();
  if (array == nullptr)
    fail(node_line(node, line_),
         quoted(key) + " must be a list of strings, not " + type_word(node));
  std::vector<std::string> out;
  for (const toml::node& element : *array) {
    if (!element.is_string())
      fail(node_line(element, line_),
           quoted(key) + " must be a list of strings; one entry is " + type_word(element));
    out.push_back(text(key, element));
  }
  return out;
}

std::vector<std::string> TomlReader::strings_or(const std::string& key,
                                                std::vector<std::string> fallback) {
  return table_.contains(key) ? strings(key) : (find(key), std::move(fallback));
}

const toml::table* TomlReader::table(const std::string& key) {
  const toml::node* node = find(key);
  if (node == nullptr) return nullptr;
  const auto* t = node->as_table();
  if (t == nullptr)
    fail(node_line(*node, line_),
         quoted(key) + " must be a table ([" + key + "]), not " + type_word(*node));
  return t;
}

std::vector<const toml::table*> TomlReader::tables(const std::string& key) {
  std::vector<const toml::table*> out;
  const toml::node* node = find(key);
  if (node == nullptr) return out;
  const auto* array = node->as_array();
  if (array == nullptr || !array->is_array_of_tables())
    fail(node_line(*node, line_),
         quoted(key) + " must be written as [[" + key + "]] tables, not " + type_word(*node));
  for (const toml::node& element : *array) out.push_back(element.as_table());
  return out;
}

void TomlReader::finish() const {
  for (auto&& [key, node] : table_) {
    const std::string name(key.str());
    if (read_.count(name) == 0) {
      const auto line = static_cast<int>(key.source().begin.line);
      // A quoted key can hold escaped control characters; the message does not repeat them.
      if (const auto control = first_control_character(name))
        fail(line > 0 ? line : node_line(node, line_),
             "a key in " + where_ + " holds a control character (" + *control + ")");
      fail(line > 0 ? line : node_line(node, line_),
           "unknown key " + quoted(name) + " in " + where_ + " (check the spelling)");
    }
  }
}

}  // namespace bb
