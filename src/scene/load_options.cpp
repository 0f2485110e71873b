// [course], [engines.*], [[observe]] and [[gate]] of a case file.
#include <algorithm>

#include "scene/backend_names.hpp"
#include "scene/engine_keys.hpp"
#include "scene/load_parts.hpp"
#include "scene/metric_names.hpp"
#include "scene/text.hpp"

namespace bb::load {

namespace {

bool contains(const std::vector<std::string>& v, const std::string& s) {
  return std::find(v.begin(), v.end(), s) != v.end();
}

std::vector<std::string> read_choices(TomlReader& r, const std::string& key,
                                      const std::vector<std::string>& known,
                                      std::vector<std::string> fallback) {
  std::vector<std::string> chosen = r.strings_or(key, std::move(fallback));
  if (chosen.empty()) r.fail(r.line_of(key), "'" + key + "' in [course] must not be empty");
  for (std::size_t i = 0; i < chosen.size(); ++i) {
    if (!contains(known, chosen[i]))
      r.fail(r.line_of(key),
             "'" + key + "' in [course] has '" + chosen[i] + "'; known: " + joined(known));
    if (std::find(chosen.begin(), chosen.begin() + i, chosen[i]) != chosen.begin() + i)
      r.fail(r.line_of(key), "'" + key + "' in [course] lists '" + chosen[i] + "' twice");
  }
  return chosen;
}

}  // namespace

void read_course(TomlReader& root, Scene& scene) {
  const toml::table empty;
  const toml::table* t = root.table("course");
  TomlReader r = sub_reader(root, t ? *t : empty, "[course]");
  scene.course.integrators =
      read_choices(r, "integrators", known_integrators(), known_integrators());
  scene.course.ground = read_choices(r, "ground", known_ground_rules(), {"mirror"});
  scene.course.friction = read_choices(r, "friction", known_friction_rules(), {"clamp"});
  r.finish();
}

void read_engines(TomlReader& root, Scene& scene) {
  const toml::table* t = root.table("engines");
  if (t == nullptr) return;
  TomlReader engines = sub_reader(root, *t, "[engines]");
  for (const std::string& engine : engine_names()) {
    const toml::table* e = engines.table(engine);
    if (e == nullptr) continue;
    TomlReader r = sub_reader(engines, *e, "[engines." + engine + "]");
    auto& values = scene.engines[engine];
    for (auto&& [key, node] : *e) {
      const std::string name(key.str());
      const EngineKey* known = find_engine_key(engine, name);
      if (known == nullptr) continue;  // finish() names it
      EngineValue v;
      v.line = r.line_of(name);
      if (known->kind == KeyKind::Boolean) {
        v.value = r.boolean_or(name, false) ? 1.0 : 0.0;
      } else if (known->kind == KeyKind::Integer) {
        v.value = r.integer(name);
        require_range(r, name, v.value, 1.0, 0.0);
      } else {
        v.value = r.number(name);
        require_range(r, name, v.value, 0.0, 0.0);
      }
      values[name] = v;
    }
    r.finish();
  }
  engines.finish();
}

void read_observes(TomlReader& root, Scene& scene) {
  for (const toml::table* t : root.tables("observe")) {
    TomlReader r = sub_reader(root, *t, "[[observe]]");
    Observe o;
    o.line = r.line();
    o.kind = r.string("kind");
    if (!contains(observable_kinds(), o.kind))
      r.fail(r.line_of("kind"),
             "unknown observable kind '" + o.kind + "'; known: " + joined(observable_kinds()));
    const std::string body = r.string("body");
    o.body = require_body(r, scene, body, r.line_of("body"));
    o.name = o.kind + "/" + body;
    if (observable_is_counted(o.kind)) {
      o.n = r.integer_or("n", 1);
      require_range(r, "n", o.n, 1.0, 0.0);
      o.name += "/" + std::to_string(o.n);
    } else if (r.has("n")) {
      r.fail(r.line_of("n"), "'n' counts events; kind '" + o.kind + "' does not take it");
    }
    r.finish();
    scene.observes.push_back(o);
  }
}

void read_gates(TomlReader& root, Scene& scene) {
  const std::vector<std::string> backends = backend_names(scene);
  for (const toml::table* t : root.tables("gate")) {
    TomlReader r = sub_reader(root, *t, "[[gate]]");
    Gate g;
    g.line = r.line();
    g.backend = r.string("backend");
    if (!contains(backends, g.backend))
      r.fail(r.line_of("backend"),
             "[[gate]] names backend '" + g.backend +
                 "', which this case does not run; it runs: " + joined(backends));
    g.metric = r.string("metric");
    const bool observable = std::any_of(scene.observes.begin(), scene.observes.end(),
                                        [&](const Observe& o) { return o.name == g.metric; });
    if (!contains(error_metric_names(), g.metric) && !observable)
      r.fail(r.line_of("metric"),
             "[[gate]] metric '" + g.metric + "' is neither an error metric (" +
                 joined(error_metric_names()) + ") nor an [[observe]] of this case");
    g.max = r.number("max");
    require_range(r, "max", g.max, 0.0, 0.0);
    r.finish();
    scene.gates.push_back(g);
  }
}

}  // namespace bb::load
