// Internal to the loader: one function per part of the case format.
#pragma once

#include <optional>
#include <string>
#include <unordered_map>
#include <unordered_set>

#include "study/case_limits.hpp"
#include "study/case_vocabulary.hpp"
#include "study/scene.hpp"
#include "study/toml_reader.hpp"
#include "study/vector_limits.hpp"

namespace bb::load {

/// Reader for a sub-table, named in messages by `where`.
TomlReader sub_reader(const TomlReader& parent, const toml::table& table, const std::string& where);

/// A [[body]] with rest_on = "<another body>": placed on it once every body is read.
struct Resting {
  int body = -1;
  std::string on;
  int line = 0;
};

/// Reads the [[body]] tables and places each body that rests on another; returns those.
std::vector<Resting> read_bodies(TomlReader& root, Scene& scene);
/// Fails unless each resting body touches the body under it (a [[contact]] names the
/// pair, or ["*"]), once the contacts are read: without one it would fall through.
void require_resting_contacts(const TomlReader& root, const Scene& scene,
                              const std::vector<Resting>& resting);

/// A [grid] as its keys give it, before any particle is made, and what it will make.
struct GridPlan {
  Grid grid;
  GridCounts counts;
  int origin_line = 0;
};
/// Reads and checks the [grid]'s keys; builds nothing.
std::optional<GridPlan> read_grid(TomlReader& root, const Scene& scene);
/// Adds the grid's particles and springs to `scene`.
void expand_grid(Scene& scene, const GridPlan& plan);

/// The case's body names and their indices, made once its bodies are all known: a lookup
/// by name costs the same however many bodies a case has. Fails on a name used twice.
class BodyNames {
 public:
  BodyNames(const TomlReader& root, const Scene& scene);
  /// Index of `name`, or -1.
  int find(const std::string& name) const;

 private:
  std::unordered_map<std::string, int> index_;
};

void read_air_and_ground(TomlReader& root, Scene& scene);
void read_waves(TomlReader& root, Scene& scene, bool has_grid);
void read_contacts(TomlReader& root, Scene& scene, const BodyNames& names);
void read_springs(TomlReader& root, Scene& scene, const BodyNames& names);
void read_hinges(TomlReader& root, Scene& scene, const BodyNames& names);
void read_impulses(TomlReader& root, Scene& scene, const BodyNames& names);
void read_course(TomlReader& root, Scene& scene);
void read_engines(TomlReader& root, Scene& scene, const EngineCatalogue& catalogue);
void read_observes(TomlReader& root, Scene& scene, const BodyNames& names,
                   const CaseVocabulary& vocabulary);
void read_gates(TomlReader& root, Scene& scene, const EngineCatalogue& catalogue);
void read_claims(TomlReader& root, Scene& scene, const EngineCatalogue& catalogue);
/// A [[claim]] with `region` (a map's claim), its keys read from `r` into `c`.
void read_region_claim(TomlReader& r, const Scene& scene, Claim& c,
                       const EngineCatalogue& catalogue);
/// Refuses a map's claim in a case without a map (two [[sweep]]s); after read_sweep. Which
/// theory bounds the map is run/'s to check (require_region_theory).
void check_region_claims(const Scene& scene);
/// Fail unless `backend`, named by `key` of `r` (`what` in messages), is one `scene` runs.
void require_runnable(const TomlReader& r, const Scene& scene, const std::string& key,
                      const std::string& what, const std::string& backend,
                      const std::vector<std::string>& runnable, const EngineCatalogue& catalogue);
void read_sweep(TomlReader& root, Scene& scene);
void read_report_and_stability(TomlReader& root, Scene& scene);
void read_baseline(TomlReader& root, Scene& scene);

/// The error metrics and the names of the case's observables, made once the [[observe]]
/// tables are read: a lookup costs the same however many a case has.
class MetricNames {
 public:
  explicit MetricNames(const Scene& scene);
  /// An error metric, or the name of one of the case's observables.
  bool contains(const std::string& name) const { return names_.count(name) > 0; }

 private:
  std::unordered_set<std::string> names_;
};
/// A number as messages show it: up to ten significant digits.
std::string show(double v);
/// Index of a named body, or a CaseError at `line` naming what is missing.
int require_body(const TomlReader& reader, const BodyNames& names, const std::string& name,
                 int line);
/// A non-zero vector scaled to unit length, or a CaseError (also when its norm is outside
/// a direction's range).
Vec3 unit_vector(const TomlReader& reader, const std::string& key, const Vec3& v);
/// Fail unless `v`, the value of `key`, lies in the range of its kind.
void require_vector_range(const TomlReader& reader, const std::string& key, const Vec3& v,
                          VectorKind kind);
/// Fail when both friction coefficients of `reader`'s table are given and the kinetic one is
/// above the static one.
void require_friction_order(const TomlReader& reader, double friction_static,
                            double friction_kinetic);
/// Fail when `body` starts deeper than rounding inside the ground, at `line`.
void refuse_ground_overlap(const TomlReader& reader, const Scene& scene, const Body& body,
                           int line);
/// Reject a vector with a z component in a 2D scene.
void require_planar(const TomlReader& reader, const Scene& scene, const std::string& key,
                    const Vec3& v);
/// Fail unless low <= value (and value <= high when given).
void require_range(const TomlReader& reader, const std::string& key, double value, double low,
                   double high, bool low_inclusive = true);

}  // namespace bb::load
