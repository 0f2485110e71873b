// Internal to the loader: one function per part of the case format.
#pragma once

#include "scene/scene.hpp"
#include "scene/toml_reader.hpp"

namespace bb::load {

/// Reader for a sub-table, named in messages by `where`.
TomlReader sub_reader(const TomlReader& parent, const toml::table& table, const std::string& where);

void read_bodies(TomlReader& root, Scene& scene);
void read_grid(TomlReader& root, Scene& scene);
void read_air_and_ground(TomlReader& root, Scene& scene);
void read_contacts(TomlReader& root, Scene& scene);
void read_springs(TomlReader& root, Scene& scene);
void read_hinges(TomlReader& root, Scene& scene);
void read_impulses(TomlReader& root, Scene& scene);
void read_course(TomlReader& root, Scene& scene);
void read_engines(TomlReader& root, Scene& scene);
void read_observes(TomlReader& root, Scene& scene);
void read_gates(TomlReader& root, Scene& scene);
void read_claims(TomlReader& root, Scene& scene);
void read_sweep(TomlReader& root, Scene& scene);
void read_report_and_stability(TomlReader& root, Scene& scene);

/// An error metric, or the name of one of the case's observables.
bool is_metric(const Scene& scene, const std::string& name);
/// A number as messages show it: up to ten significant digits.
std::string show(double v);
/// Index of a named body, or a CaseError at `line` naming what is missing.
int require_body(const TomlReader& reader, const Scene& scene, const std::string& name, int line);
/// A non-zero vector scaled to unit length, or a CaseError.
Vec3 unit_vector(const TomlReader& reader, const std::string& key, const Vec3& v);
/// Reject a vector with a z component in a 2D scene.
void require_planar(const TomlReader& reader, const Scene& scene, const std::string& key,
                    const Vec3& v);
/// Fail unless low <= value (and value <= high when given).
void require_range(const TomlReader& reader, const std::string& key, double value, double low,
                   double high, bool low_inclusive = true);

}  // namespace bb::load
