// [[sweep]] of a case file: one parameter, its values (a list or a range), and what the
// page says beside it; a second [[sweep]] makes the pair a map.
#include <algorithm>
#include <cmath>

#include "model/contact_pairs.hpp"
#include "model/initial_overlap.hpp"
#include "model/text.hpp"
#include "study/case_limits.hpp"
#include "study/load_parts.hpp"
#include "study/sweep_parameter.hpp"

namespace bb::load {

namespace {

std::vector<double> read_values(TomlReader& r) {
  if (r.has("values") == r.has("range"))
    r.fail(r.line(),
           "[[sweep]] needs 'values' = [...] or 'range' = [from, to, count], one of them");
  if (r.has("values")) {
    std::vector<double> values = r.numbers("values");
    if (values.size() < 2) r.fail(r.line_of("values"), "[[sweep]] 'values' needs at least two");
    if (values.size() > kMaxSweepValues)
      r.fail(r.line_of("values"), "[[sweep]] 'values' has " + std::to_string(values.size()) +
                                      "; at most " + std::to_string(kMaxSweepValues));
    return values;
  }
  const std::vector<double> range = r.numbers("range", 3);
  const double count = range[2];
  if (count != std::floor(count) || count < 2 || count > kMaxSweepValues)
    r.fail(r.line_of("range"),
           "[[sweep]] 'range' = [from, to, count]: count must be a whole "
           "number from 2 to " +
               std::to_string(kMaxSweepValues) + ", not " + show(count));
  if (!(range[0] < range[1]))
    r.fail(r.line_of("range"), "[[sweep]] 'range' = [from, to, count] needs from < to");
  return sweep_range(range[0], range[1], static_cast<int>(count));
}

/// A sweep of a body's position or size must not move it inside the ground or inside a
/// body it touches by a [[contact]], at any point: the first such value is refused.
void refuse_swept_overlaps(const TomlReader& r, const Scene& scene, const Sweep& s,
                           const std::string& key) {
  const std::vector<std::string> p = sweep_path_parts(s.parameter);
  if (p[0] != "body" || !(p[2] == "position" || p[2] == "radius" || p[2] == "half_extents")) return;
  const int index = scene.body_index(p[1]);
  // The bodies it may touch, found once.
  std::vector<int> partners;
  for (const ContactPair& pair : contact_pairs(scene))
    if (!pair.ground() && (pair.a == index || pair.b == index))
      partners.push_back(pair.a == index ? pair.b : pair.a);
  Scene one;
  one.bodies = {scene.bodies[index]};
  for (double v : s.values) {
    set_sweep_parameter(one, s.parameter, v);
    const Body& swept = one.bodies[0];
    const std::string at =
        "[[sweep]] the value " + short_number(v) + " for '" + s.parameter + "' puts ";
    if (scene.ground && !swept.fixed)
      if (const double depth = ground_depth(swept, *scene.ground); depth > kOverlapRounding)
        r.fail(r.line_of(key), at + "body '" + swept.name + "' " + short_number(depth) +
                                   " m inside the ground; no backend can resolve a start inside");
    for (int other : partners)
      if (const double depth = overlap_depth(swept, scene.bodies[other]); depth > kOverlapRounding)
        r.fail(r.line_of(key), at + "bodies '" + swept.name + "' and '" + scene.bodies[other].name +
                                   "' " + short_number(depth) +
                                   " m inside each other, and a [[contact]] makes them touch");
  }
}

/// Two parameters of one part of the case (the ground's two frictions, the bodies' positions
/// and sizes, the waves) bound each other, so a map checks them together at every point;
/// any other pair is checked one value at a time.
bool bound_together(const std::string& a, const std::string& b) {
  return sweep_path_parts(a)[0] == sweep_path_parts(b)[0] && a != "dt";
}

/// One [[sweep]] table: its parameter and values, each value checked alone.
Sweep read_one_sweep(TomlReader& r, const Scene& scene) {
  Sweep s;
  s.line = r.line();
  s.parameter = r.string("parameter");
  if (const std::string problem = sweep_path_problem(scene, s.parameter); !problem.empty())
    r.fail(r.line_of("parameter"), "[[sweep]] 'parameter' " + problem);
  s.values = read_values(r);
  const std::string key = r.has("values") ? "values" : "range";
  // Each value is a run of the whole case and a row of the page: one value twice is the
  // same point twice (a range's steps below a double's resolution make such twins too).
  std::vector<double> sorted = s.values;
  std::sort(sorted.begin(), sorted.end());
  if (const auto twin = std::adjacent_find(sorted.begin(), sorted.end()); twin != sorted.end())
    r.fail(r.line_of(key), "[[sweep]] '" + key + "' gives the value " + short_number(*twin) +
                               " twice; each value is one point of the sweep");
  for (double v : s.values)
    if (const std::string problem = sweep_value_problem(scene, s.parameter, v); !problem.empty())
      r.fail(r.line_of(key), "[[sweep]] " + problem);
  refuse_swept_overlaps(r, scene, s, key);
  return s;
}

/// The second [[sweep]] of a map, checked at every value of the first where the two bound
/// each other; it takes no page keys of its own (the map's page is the first's).
Sweep read_second_sweep(TomlReader& r, const Scene& scene, const Sweep& first) {
  Sweep s = read_one_sweep(r, scene);
  if (s.parameter == first.parameter)
    r.fail(r.line_of("parameter"),
           "[[sweep]] 'parameter' '" + s.parameter + "' is the first [[sweep]]'s too (line " +
               std::to_string(first.line) + "); a map varies two parameters");
  for (const char* key : {"published", "onset", "onset_above", "colour"})
    if (r.has(key))
      r.fail(r.line_of(key), std::string("[[sweep]] '") + key +
                                 "' belongs in the first [[sweep]] of a map (line " +
                                 std::to_string(first.line) + "), whose page the map is");
  if (!bound_together(first.parameter, s.parameter)) return s;
  const std::string key = r.has("values") ? "values" : "range";
  for (double a : first.values) {
    Scene at = scene;
    set_sweep_parameter(at, first.parameter, a);
    for (double b : s.values)
      if (const std::string problem = sweep_value_problem(at, s.parameter, b); !problem.empty())
        r.fail(r.line_of(key), "[[sweep]] at " + first.parameter + " = " + short_number(a) +
                                   " (the first [[sweep]]), " + problem);
    refuse_swept_overlaps(r, at, s, key);
  }
  return s;
}

}  // namespace

void read_sweep(TomlReader& root, Scene& scene) {
  const std::vector<const toml::table*> sweeps = root.tables("sweep");
  if (sweeps.empty()) return;
  TomlReader r = sub_reader(root, *sweeps.front(), "[[sweep]]");
  if (sweeps.size() > 2) {
    const TomlReader third = sub_reader(root, *sweeps[2], "[[sweep]]");
    third.fail(third.line(),
               "a case varies one parameter, or two as a map; this is its third [[sweep]] (the "
               "first is on line " +
                   std::to_string(r.line()) + ")");
  }
  Sweep s = read_one_sweep(r, scene);
  s.published = r.string_or("published", "");
  s.onset = r.string_or("onset", "");
  if (!s.onset.empty() && !MetricNames(scene).contains(s.onset))
    r.fail(r.line_of("onset"), "[[sweep]] 'onset' '" + s.onset +
                                   "' is neither an error metric nor an [[observe]] of this case");
  if (r.has("onset_above") && s.onset.empty())
    r.fail(r.line_of("onset_above"), "[[sweep]] 'onset_above' needs an 'onset' to compare");
  s.onset_above = r.number_or("onset_above", 0.0);
  s.colour = r.string_or("colour", "");
  if (!s.colour.empty() && !MetricNames(scene).contains(s.colour))
    r.fail(r.line_of("colour"), "[[sweep]] 'colour' '" + s.colour +
                                    "' is neither an error metric nor an [[observe]] of this case");
  if (!s.colour.empty() && sweeps.size() < 2)
    r.fail(r.line_of("colour"),
           "[[sweep]] 'colour' colours a map's points: it needs a second [[sweep]]");
  r.finish();
  scene.sweep = s;
  if (sweeps.size() < 2) return;
  TomlReader second = sub_reader(root, *sweeps[1], "[[sweep]]");
  scene.second_sweep = read_second_sweep(second, scene, s);
  second.finish();
}

}  // namespace bb::load
