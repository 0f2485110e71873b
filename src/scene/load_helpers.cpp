#include <sstream>

#include "scene/load_parts.hpp"

namespace bb::load {

std::string show(double v) {
  std::ostringstream s;
  s.precision(10);
  s << v;
  return s.str();
}

TomlReader sub_reader(const TomlReader& parent, const toml::table& table,
                      const std::string& where) {
  return TomlReader(table, parent.file(), where, node_line(table, parent.line()));
}

int require_body(const TomlReader& reader, const Scene& scene, const std::string& name, int line) {
  const int index = scene.body_index(name);
  if (index < 0)
    reader.fail(line,
                reader.where() + " names body '" + name + "', which the case does not define");
  return index;
}

Vec3 unit_vector(const TomlReader& reader, const std::string& key, const Vec3& v) {
  const double length = v.norm();
  if (length < 1e-12)
    reader.fail(reader.line_of(key), "'" + key + "' in " + reader.where() +
                                         " must not be the zero vector (it gives a direction)");
  return v / length;
}

void require_planar(const TomlReader& reader, const Scene& scene, const std::string& key,
                    const Vec3& v) {
  if (scene.dims == 2 && v.z() != 0.0)
    reader.fail(reader.line_of(key), "'" + key + "' in " + reader.where() +
                                         " has a z component, but the case is 2D (dims = 2): "
                                         "motion stays in the x-y plane");
}

void require_range(const TomlReader& reader, const std::string& key, double value, double low,
                   double high, bool low_inclusive) {
  const bool too_low = low_inclusive ? value < low : value <= low;
  const bool too_high = high > low && value > high;
  if (too_low || too_high) {
    std::string rule = low_inclusive ? "at least " + show(low) : "greater than " + show(low);
    if (high > low) rule = "between " + show(low) + " and " + show(high);
    reader.fail(reader.line_of(key),
                "'" + key + "' in " + reader.where() + " must be " + rule + ", not " + show(value));
  }
}

}  // namespace bb::load
