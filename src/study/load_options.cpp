// [course], [engines.*], [[gate]], [[claim]], [report] and [stability] of a case file
// ([[observe]]: load_observes.cpp).
#include <algorithm>
#include <unordered_set>

#include "model/text.hpp"
#include "seam/engine_keys.hpp"
#include "study/backend_names.hpp"
#include "study/case_limits.hpp"
#include "study/load_parts.hpp"
#include "study/metric_names.hpp"
#include "study/vector_limits.hpp"

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
  scene.course.hit = read_choices(r, "hit", known_hit_rules(), {"seed-plank"});
  scene.course.spin = read_choices(r, "spin", known_spin_rules(), {"free"});
  r.finish();
}

void read_engines(TomlReader& root, Scene& scene, const EngineCatalogue& catalogue) {
  const toml::table* t = root.table("engines");
  if (t == nullptr) return;
  TomlReader engines = sub_reader(root, *t, "[engines]");
  for (const EngineDescription& description : catalogue) {
    const std::string& engine = description.engine;
    const toml::table* e = engines.table(engine);
    if (e == nullptr) continue;
    TomlReader r = sub_reader(engines, *e, "[engines." + engine + "]");
    auto& values = scene.engines[engine];
    for (auto&& [key, node] : *e) {
      const std::string name(key.str());
      const EngineKey* known = find_engine_key(description, name);
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

MetricNames::MetricNames(const Scene& scene) {
  for (const std::string& m : error_metric_names()) names_.insert(m);
  for (const Observe& o : scene.observes) names_.insert(o.name);
}

void require_runnable(const TomlReader& r, const Scene& scene, const std::string& key,
                      const std::string& what, const std::string& backend,
                      const std::vector<std::string>& runnable, const EngineCatalogue& catalogue) {
  // A program's trajectory is given on the command line, not in the case.
  if (contains(runnable, backend) || is_import_name(backend)) return;
  const std::vector<std::string> known = backend_names(scene, catalogue);
  if (!contains(known, backend))
    r.fail(r.line_of(key), what + " names backend '" + backend +
                               "', which this case does not run; it runs: " + joined(runnable));
  r.fail(r.line_of(key), what + " names backend '" + backend + "', which cannot run this case: " +
                             why_backend_cannot_run(scene, backend, catalogue) +
                             "; it runs: " + joined(runnable));
}

void read_gates(TomlReader& root, Scene& scene, const EngineCatalogue& catalogue) {
  const std::vector<std::string> backends = runnable_backend_names(scene, catalogue);
  const MetricNames metrics(scene);
  for (const toml::table* t : root.tables("gate")) {
    TomlReader r = sub_reader(root, *t, "[[gate]]");
    Gate g;
    g.line = r.line();
    g.backend = r.string("backend");
    require_runnable(r, scene, "backend", "[[gate]]", g.backend, backends, catalogue);
    g.metric = r.string("metric");
    if (!metrics.contains(g.metric))
      r.fail(r.line_of("metric"),
             "[[gate]] metric '" + g.metric + "' is neither an error metric (" +
                 joined(error_metric_names()) + ") nor an [[observe]] of this case");
    g.max = r.number("max");
    require_range(r, "max", g.max, 0.0, 0.0);
    r.finish();
    scene.gates.push_back(g);
  }
}

namespace {

/// One side of a [[claim]], `key` "left" or "right": a number, or
/// "<backend or *>:<metric or observable>" naming something the case has.
ClaimSide read_claim_side(TomlReader& r, const Scene& scene, const std::string& key,
                          const std::vector<std::string>& backends, const MetricNames& metrics,
                          const EngineCatalogue& catalogue) {
  ClaimSide side;
  if (r.holds_number(key)) {
    side.number = r.number(key);
    return side;
  }
  const std::string text = r.string(key);
  const std::size_t colon = text.find(':');
  if (colon == std::string::npos)
    r.fail(r.line_of(key), "[[claim]] '" + key + "' is '" + text +
                               "'; write a number or '<backend or *>:<metric or observable>'");
  side.backend = text.substr(0, colon);
  side.metric = text.substr(colon + 1);
  if (side.backend != "*")
    require_runnable(r, scene, key, "[[claim]] '" + key + "'", side.backend, backends, catalogue);
  if (!metrics.contains(side.metric))
    r.fail(r.line_of(key), "[[claim]] '" + key + "' names '" + side.metric +
                               "', which is neither an error metric (" +
                               joined(error_metric_names()) + ") nor an [[observe]] of this case");
  return side;
}

/// `quote` and `own`: the course text's words the claim tests, or a claim of the case's own.
void read_claim_source(TomlReader& r, Claim& c) {
  c.own = r.boolean_or("own", false);
  c.quote = r.string_or("quote", "");
  if (r.has("quote") && c.quote.find_first_not_of(" \t\n\r") == std::string::npos)
    r.fail(r.line_of("quote"), "[[claim]] 'quote' must not be empty");
  if (c.quote.empty() && !c.own)
    r.fail(c.line,
           "[[claim]] needs 'quote', the course text's words it tests, or 'own = true' for a "
           "claim the text does not make (the case's own)");
}

/// `diverged` and `compare`: what a diverged run counts as, and whether each side is read
/// as its distance from the reference.
void read_claim_reading(TomlReader& r, Claim& c) {
  const std::string diverged = r.string_or("diverged", "");
  if (diverged == "holds") {
    c.diverged = DivergedCounts::Holds;
  } else if (diverged == "fails") {
    c.diverged = DivergedCounts::Fails;
  } else if (r.has("diverged")) {
    r.fail(r.line_of("diverged"), "[[claim]] 'diverged' is '" + diverged +
                                      "'; known: holds (a divergence is evidence for the "
                                      "claim), fails (evidence against it)");
  }
  const std::string compare = r.string_or("compare", "value");
  if (compare != "value" && compare != "error")
    r.fail(r.line_of("compare"), "[[claim]] 'compare' is '" + compare + "'; known: value, error");
  c.against_reference = compare == "error";
  // The reference's distance from itself is zero by definition: nothing to compare.
  for (const auto& [key, side] : {std::pair{"left", &c.left}, std::pair{"right", &c.right}})
    if (c.against_reference && side->backend == kReferenceName)
      r.fail(r.line_of(key), std::string("[[claim]] with compare = \"error\" reads each side "
                                         "as its distance from the reference; '") +
                                 key + "' names the reference itself");
}

}  // namespace

void read_claims(TomlReader& root, Scene& scene, const EngineCatalogue& catalogue) {
  const std::vector<std::string> backends = runnable_backend_names(scene, catalogue);
  const MetricNames metrics(scene);
  const std::vector<std::string> ops = {"<", "<=", ">", ">=", "~"};
  for (const toml::table* t : root.tables("claim")) {
    TomlReader r = sub_reader(root, *t, "[[claim]]");
    Claim c;
    c.line = r.line();
    c.text = r.string("text");
    if (c.text.empty()) r.fail(r.line_of("text"), "[[claim]] 'text' must not be empty");
    c.seed = r.string_or("seed", "");
    if (r.has("region")) {
      read_region_claim(r, scene, c, catalogue);
      read_claim_source(r, c);
      r.finish();
      scene.claims.push_back(c);
      continue;
    }
    c.left = read_claim_side(r, scene, "left", backends, metrics, catalogue);
    c.op = r.string("op");
    if (!contains(ops, c.op))
      r.fail(r.line_of("op"), "[[claim]] 'op' is '" + c.op + "'; known: " + joined(ops));
    c.right = read_claim_side(r, scene, "right", backends, metrics, catalogue);
    if (c.left.is_number())
      r.fail(r.line_of("left"), "[[claim]] 'left' must name a quantity, not a number");
    if (c.right.backend == "*" && c.left.backend != "*")
      r.fail(r.line_of("right"),
             "[[claim]] 'right' says '*' (each backend) where 'left' names one backend");
    c.tolerance = r.number_or("tolerance", 0.0);
    require_range(r, "tolerance", c.tolerance, 0.0, 0.0, true);
    if (c.op == "~" && !r.has("tolerance"))
      r.fail(r.line_of("op"), "[[claim]] with '~' needs a 'tolerance'");
    read_claim_source(r, c);
    read_claim_reading(r, c);
    r.finish();
    scene.claims.push_back(c);
  }
}

namespace {

/// Every trial of the stability search runs the whole duration: at dt_min it takes
/// duration / dt_min steps, which may not pass the cap of any run. A default dt_min (a
/// quarter of the finest dt) is raised to the cap; a dt_min the case gives (line
/// `dt_min_line`), or a dt_max (`dt_max_line`) that leaves no step within the cap, is refused.
void refuse_endless_trials(const TomlReader& root, Scene& scene, int dt_min_line, int dt_max_line) {
  StabilityOptions& s = scene.stability;
  const double shortest = scene.duration / kMaxStepsPerRun;
  if (s.dt_min >= shortest * (1.0 - 1e-12)) return;
  const auto refuse = [&](const std::string& key, double value, int line) {
    root.fail(line, "'" + key + "' in [stability] is " + show(value) + " s: a trial over the " +
                        show(scene.duration) + " s duration would take " +
                        show(scene.duration / value) + " steps; a run may take at most " +
                        show(kMaxStepsPerRun) + " (a step of at least " + show(shortest) + " s)");
  };
  if (dt_min_line > 0) refuse("dt_min", s.dt_min, dt_min_line);
  if (s.dt_max <= shortest) refuse("dt_max", s.dt_max, dt_max_line);
  s.dt_min = shortest;
}

}  // namespace

void read_report_and_stability(TomlReader& root, Scene& scene) {
  if (const toml::table* t = root.table("report")) {
    TomlReader r = sub_reader(root, *t, "[report]");
    scene.report.metrics = r.strings_or("metrics", scene.report.metrics);
    if (scene.report.metrics.empty())
      r.fail(r.line_of("metrics"), "'metrics' in [report] must not be empty");
    const MetricNames known(scene);
    std::unordered_set<std::string> listed;
    for (const std::string& m : scene.report.metrics) {
      if (!known.contains(m))
        r.fail(r.line_of("metrics"), "[report] metric '" + m + "' is neither an error metric (" +
                                         joined(error_metric_names()) +
                                         ") nor an [[observe]] of this case");
      // Each metric is a diagram of its own file: the same one twice would collide.
      if (!listed.insert(m).second)
        r.fail(r.line_of("metrics"), "'metrics' in [report] lists '" + m +
                                         "' twice; each gets its own diagram, name it once");
    }
    scene.report.target = r.number_or("target", scene.report.target);
    require_range(r, "target", scene.report.target, 0.0, 0.0, false);
    r.finish();
  }
  StabilityOptions& s = scene.stability;
  int dt_min_line = 0, dt_max_line = 0;
  if (const toml::table* t = root.table("stability")) {
    TomlReader r = sub_reader(root, *t, "[stability]");
    if (r.has("energy_factor"))
      r.fail(r.line_of("energy_factor"),
             "'energy_factor' is gone: stable now means bounded (docs/design.md); "
             "'growth_factor' says how much faster than steady drift the energy's rise may "
             "grow over a quarter of the run before it counts as compounding");
    s.growth_factor = r.number_or("growth_factor", s.growth_factor);
    require_range(r, "growth_factor", s.growth_factor, 1.0, 0.0, false);
    // Absent bounds stay 0 and get their defaults below.
    if (r.has("dt_min")) {
      s.dt_min = r.number("dt_min");
      dt_min_line = r.line_of("dt_min");
      require_range(r, "dt_min", s.dt_min, 0.0, 0.0, false);
    }
    if (r.has("dt_max")) {
      s.dt_max = r.number("dt_max");
      dt_max_line = r.line_of("dt_max");
      require_range(r, "dt_max", s.dt_max, s.dt_min, 0.0, false);
      if (s.dt_max > scene.duration)
        r.fail(r.line_of("dt_max"), "'dt_max' in [stability] is longer than the duration");
    }
    r.finish();
  }
  // Defaults: from a quarter of the finest step to a sixteenth of the run, the largest step
  // whose run has enough steps to show how its energy grows (metrics/energy_growth.hpp).
  if (s.dt_min == 0.0)
    s.dt_min = std::min(scene.dt.back() / 4.0, s.dt_max > 0 ? s.dt_max / 2 : 1e300);
  if (s.dt_max == 0.0) s.dt_max = std::max(scene.duration / 16.0, 2.0 * s.dt_min);
  refuse_endless_trials(root, scene, dt_min_line, dt_max_line);
}

}  // namespace bb::load
