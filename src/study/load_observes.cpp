// [[observe]] of a case file: each observable the case asks for, its kind from the vocabulary
// the loader is handed, its body, its count and its thresholds; one name each.
#include "model/text.hpp"
#include "study/load_parts.hpp"
#include "study/vector_limits.hpp"

namespace bb::load {

/// The kind `name` of the vocabulary, or nullptr.
const ObservableWord* find_word(const CaseVocabulary& vocabulary, const std::string& name) {
  for (const ObservableWord& w : vocabulary.observables)
    if (w.name == name) return &w;
  return nullptr;
}

std::string known_kinds(const CaseVocabulary& vocabulary) {
  std::vector<std::string> names;
  for (const ObservableWord& w : vocabulary.observables) names.push_back(w.name);
  return joined(names);
}

/// An [[observe]]'s `rest_speed`, `level` and `axis`, for the kinds that take them: a body has
/// one rest speed, so two of its [[observe]] may not give two; a level is required where
/// taken; a spin is signed about z in 2D and about a given axis in 3D.
void read_observe_thresholds(TomlReader& r, const Scene& scene, const ObservableWord& word,
                             Observe& o) {
  if (r.has("rest_speed") && !word.rest_speed)
    r.fail(r.line_of("rest_speed"), "kind '" + o.kind + "' does not take 'rest_speed'");
  if (r.has("rest_speed")) {
    o.rest_speed = r.number("rest_speed");
    require_range(r, "rest_speed", *o.rest_speed, 0.0, vector_limit(VectorKind::Velocity).most);
    for (const Observe& other : scene.observes)
      if (other.body == o.body && other.rest_speed && *other.rest_speed != *o.rest_speed)
        r.fail(r.line_of("rest_speed"), "'rest_speed' " + show(*o.rest_speed) +
                                            " differs from the " + show(*other.rest_speed) +
                                            " line " + std::to_string(other.line) +
                                            " gives the same body: a body has one rest speed");
  }
  // A level: a height along -gravity, within the positions a case may give.
  if (r.has("level") && !word.level)
    r.fail(r.line_of("level"), "kind '" + o.kind + "' does not take 'level'");
  if (word.level) {
    const double most = vector_limit(VectorKind::Position).most;
    if (!r.has("level"))
      r.fail(o.line,
             "kind '" + o.kind + "' needs 'level': the height (m) whose crossings it watches");
    o.level = r.number("level");
    require_range(r, "level", *o.level, -most, most);
  }
  if (r.has("axis") && !word.axis)
    r.fail(r.line_of("axis"), "kind '" + o.kind + "' does not take 'axis'");
  if (!word.axis) return;
  if (scene.dims == 3 && !r.has("axis"))
    r.fail(o.line, "kind '" + o.kind + "' in a 3D case needs 'axis': the spin is signed about it");
  const Vec3 axis = r.vec3_or("axis", o.axis);
  if (scene.dims == 2 && (axis.x() != 0.0 || axis.y() != 0.0))
    r.fail(r.line_of("axis"),
           "in a 2D case a spin is about z: 'axis' must be [0, 0, 1] or [0, 0, -1]");
  o.axis = unit_vector(r, "axis", axis);
}

void read_observes(TomlReader& root, Scene& scene, const BodyNames& names,
                   const CaseVocabulary& vocabulary) {
  for (const toml::table* t : root.tables("observe")) {
    TomlReader r = sub_reader(root, *t, "[[observe]]");
    Observe o;
    o.line = r.line();
    o.kind = r.string("kind");
    const ObservableWord* word = find_word(vocabulary, o.kind);
    if (word == nullptr)
      r.fail(r.line_of("kind"),
             "unknown observable kind '" + o.kind + "'; known: " + known_kinds(vocabulary));
    if (word->scene_wide) {
      // A quantity of the whole scene: it is named by its kind and takes no body.
      if (r.has("body"))
        r.fail(r.line_of("body"),
               "kind '" + o.kind + "' describes the whole scene; it takes no 'body'");
      o.name = o.kind;
    } else {
      const std::string body = r.string("body");
      o.body = require_body(r, names, body, r.line_of("body"));
      o.name = o.kind + "/" + body;
    }
    if (word->counted) {
      o.n = r.integer_or("n", 1);
      require_range(r, "n", o.n, 1.0, 0.0);
      o.name += "/" + std::to_string(o.n);
    } else if (r.has("n")) {
      r.fail(r.line_of("n"), "'n' counts events; kind '" + o.kind + "' does not take it");
    }
    // Results, gates and the events' traces know an observable by its name alone.
    for (const Observe& first : scene.observes)
      if (first.name == o.name)
        r.fail(o.line, "[[observe]] '" + o.name + "' is given twice (first on line " +
                           std::to_string(first.line) + "): an observable is named by its kind, " +
                           "body and n alone, so two would share one name");
    read_observe_thresholds(r, scene, *word, o);
    r.finish();
    scene.observes.push_back(o);
  }
}

}  // namespace bb::load
