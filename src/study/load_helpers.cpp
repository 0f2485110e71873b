#include <sstream>

#include "model/initial_overlap.hpp"
#include "model/text.hpp"
#include "study/load_parts.hpp"

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

BodyNames::BodyNames(const TomlReader& root, const Scene& scene) {
  index_.reserve(scene.bodies.size());
  for (std::size_t i = 0; i < scene.bodies.size(); ++i) {
    const Body& b = scene.bodies[i];
    const auto [at, fresh] = index_.emplace(b.name, static_cast<int>(i));
    if (!fresh)
      root.fail(b.line, "body name '" + b.name + "' is used twice (first on line " +
                            std::to_string(scene.bodies[at->second].line) + ")");
  }
}

int BodyNames::find(const std::string& name) const {
  const auto at = index_.find(name);
  return at == index_.end() ? -1 : at->second;
}

int require_body(const TomlReader& reader, const BodyNames& names, const std::string& name,
                 int line) {
  const int index = names.find(name);
  if (index < 0)
    reader.fail(line,
                reader.where() + " names body '" + name + "', which the case does not define");
  return index;
}

Vec3 unit_vector(const TomlReader& reader, const std::string& key, const Vec3& v) {
  if (v.isZero(0.0))
    reader.fail(reader.line_of(key), "'" + key + "' in " + reader.where() +
                                         " must not be the zero vector (it gives a direction)");
  require_vector_range(reader, key, v, VectorKind::Direction);
  return v.normalized();
}

void require_vector_range(const TomlReader& reader, const std::string& key, const Vec3& v,
                          VectorKind kind) {
  if (const std::string problem = vector_limit_problem(kind, v); !problem.empty())
    reader.fail(reader.line_of(key), "'" + key + "' in " + reader.where() + " " + problem);
}

void require_friction_order(const TomlReader& reader, double friction_static,
                            double friction_kinetic) {
  if (reader.has("friction_static") && reader.has("friction_kinetic") &&
      friction_kinetic > friction_static)
    reader.fail(reader.line_of("friction_kinetic"),
                "'friction_kinetic' (" + show(friction_kinetic) + ") is above 'friction_static' (" +
                    show(friction_static) + ") in " + reader.where() +
                    ": a body that stops would be pushed off again by the difference (the "
                    "reference then gains energy); give friction_kinetic <= friction_static");
}

void refuse_ground_overlap(const TomlReader& reader, const Scene& scene, const Body& body,
                           int line) {
  if (!scene.ground || body.fixed) return;
  const double depth = ground_depth(body, *scene.ground);
  if (depth > kOverlapRounding)
    reader.fail(line, "body '" + body.name + "' starts " + short_number(depth) +
                          " m inside the ground; no backend can resolve a start inside (the "
                          "reference falls through): move it out (overlaps up to " +
                          short_number(kOverlapRounding) + " m are rounding)");
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
    if (high > low)
      rule = low_inclusive ? "between " + short_number(low) + " and " + short_number(high)
                           : rule + " and at most " + short_number(high);
    reader.fail(reader.line_of(key),
                "'" + key + "' in " + reader.where() + " must be " + rule + ", not " + show(value));
  }
}

}  // namespace bb::load
