// [air], [ground], [[contact]], [[spring]] and [[hinge]] of a case file.
#include <algorithm>
#include <map>

#include "model/contact_pairs.hpp"
#include "model/initial_overlap.hpp"
#include "model/text.hpp"
#include "study/load_parts.hpp"
#include "study/vector_limits.hpp"

namespace bb::load {

namespace {

/// A ["a", "b"] pair of distinct known bodies; also ["*"] when `star` is allowed.
std::pair<int, int> read_pair(TomlReader& r, const BodyNames& names_index, bool star,
                              bool& all_pairs) {
  const std::vector<std::string> names = r.strings("bodies");
  const int line = r.line_of("bodies");
  all_pairs = star && names.size() == 1 && names[0] == "*";
  if (all_pairs) return {-1, -1};
  if (names.size() != 2)
    r.fail(line, "'bodies' in " + r.where() + " must name two bodies" +
                     (star ? std::string(" (or be [\"*\"] for every pair)") : std::string()));
  const int a = require_body(r, names_index, names[0], line);
  const int b = require_body(r, names_index, names[1], line);
  if (a == b) r.fail(line, r.where() + " joins body '" + names[0] + "' to itself");
  return {a, b};
}

/// The [[contact]] that makes bodies `a` and `b` touch: the one naming them, else ["*"].
const Contact& contact_of(const Scene& scene, int a, int b) {
  const Contact* every = nullptr;
  for (const Contact& c : scene.contacts) {
    if (c.ground) continue;
    if ((c.body_a == a && c.body_b == b) || (c.body_a == b && c.body_b == a)) return c;
    if (c.all_pairs && every == nullptr) every = &c;
  }
  return *every;
}

/// Bodies a [[contact]] makes touch must not start inside each other: no backend resolves
/// such a start the same way (or at all).
void refuse_body_overlaps(const TomlReader& root, const Scene& scene) {
  if (scene.contacts.empty()) return;
  for (const ContactPair& p : contact_pairs(scene)) {
    if (p.ground()) continue;
    const Body& a = scene.bodies[p.a];
    const Body& b = scene.bodies[p.b];
    const double depth = overlap_depth(a, b);
    if (depth > kOverlapRounding)
      root.fail(contact_of(scene, p.a, p.b).line,
                "bodies '" + a.name + "' and '" + b.name + "' start " + short_number(depth) +
                    " m inside each other, and this [[contact]] makes them touch; no backend "
                    "can resolve a start inside: move them apart (overlaps up to " +
                    short_number(kOverlapRounding) + " m are rounding)");
  }
}

}  // namespace

void read_air_and_ground(TomlReader& root, Scene& scene) {
  if (const toml::table* t = root.table("air")) {
    TomlReader r = sub_reader(root, *t, "[air]");
    Air air;
    air.density = r.number_or("density", air.density);
    require_range(r, "density", air.density, 0.0, 0.0);
    air.wind = r.vec3_or("wind", {});
    require_planar(r, scene, "wind", air.wind);
    require_vector_range(r, "wind", air.wind, VectorKind::Wind);
    r.finish();
    scene.air = air;
  }
  if (const toml::table* t = root.table("water")) {
    TomlReader r = sub_reader(root, *t, "[water]");
    Water water;
    water.density = r.number_or("density", water.density);
    require_range(r, "density", water.density, 0.0, 0.0, false);
    r.finish();
    scene.water = water;
  }
  if (const toml::table* t = root.table("ground")) {
    TomlReader r = sub_reader(root, *t, "[ground]");
    Ground g;
    g.point = r.vec3_or("point", {});
    require_planar(r, scene, "point", g.point);
    require_vector_range(r, "point", g.point, VectorKind::Position);
    const Vec3 normal = r.vec3_or("normal", g.normal);
    require_planar(r, scene, "normal", normal);
    g.normal = unit_vector(r, "normal", normal);
    g.restitution = r.number_or("restitution", 0.0);
    require_range(r, "restitution", g.restitution, 0.0, 1.0);
    // One coefficient given sets both (Coulomb's law with one coefficient): a static one of
    // 0 beside a kinetic one would push a stopped body off again.
    g.friction_static = r.number_or("friction_static", r.number_or("friction_kinetic", 0.0));
    require_range(r, "friction_static", g.friction_static, 0.0, 0.0);
    g.friction_kinetic = r.number_or("friction_kinetic", g.friction_static);
    require_range(r, "friction_kinetic", g.friction_kinetic, 0.0, 0.0);
    require_friction_order(r, g.friction_static, g.friction_kinetic);
    r.finish();
    scene.ground = g;
  }
}

void read_contacts(TomlReader& root, Scene& scene, const BodyNames& names_index) {
  // Each pair (b = -1: with the ground) and ["*"] may be named once: the line that did.
  std::map<std::pair<int, int>, int> named;
  int every = 0;
  for (const toml::table* t : root.tables("contact")) {
    TomlReader r = sub_reader(root, *t, "[[contact]]");
    Contact c;
    c.line = r.line();
    // ["<body>", "ground"]: that body's contact with the ground, when the case has one.
    const std::vector<std::string> names = r.strings("bodies");
    const auto ground_at = std::find(names.begin(), names.end(), "ground");
    if (scene.ground && names.size() == 2 && ground_at != names.end()) {
      if (names_index.find("ground") >= 0)
        r.fail(r.line_of("bodies"), "'ground' in " + r.where() +
                                        " could be the [ground] or the body called 'ground': "
                                        "rename the body");
      const std::string& body = names[ground_at == names.begin() ? 1 : 0];
      c.ground = true;
      c.body_a = require_body(r, names_index, body, r.line_of("bodies"));
      if (scene.bodies[c.body_a].fixed)
        r.fail(r.line_of("bodies"), "body '" + body + "' is fixed and never touches the ground");
      if (const auto [at, fresh] = named.emplace(std::pair{c.body_a, -1}, c.line); !fresh)
        r.fail(r.line_of("bodies"), "[[contact]] joins '" + body +
                                        "' and the ground, as the [[contact]] on line " +
                                        std::to_string(at->second) + " does; give each pair once");
    } else {
      const auto [a, b] = read_pair(r, names_index, true, c.all_pairs);
      c.body_a = a;
      c.body_b = b;
      if (c.all_pairs && every > 0)
        r.fail(r.line_of("bodies"), "[[contact]] [\"*\"] is given twice (first on line " +
                                        std::to_string(every) + "); give it once");
      if (c.all_pairs) every = c.line;
      const auto key = std::minmax(a, b);
      if (!c.all_pairs)
        if (const auto [at, fresh] = named.emplace(std::pair{key.first, key.second}, c.line);
            !fresh)
          r.fail(r.line_of("bodies"), "[[contact]] joins '" + names[0] + "' and '" + names[1] +
                                          "', as the [[contact]] on line " +
                                          std::to_string(at->second) +
                                          " does; give each pair once");
    }
    c.restitution = r.number_or("restitution", 0.0);
    require_range(r, "restitution", c.restitution, 0.0, 1.0);
    // `friction` sets both coefficients; or friction_static and friction_kinetic, as
    // [ground] takes them (either alone sets both).
    if (r.has("friction") && (r.has("friction_static") || r.has("friction_kinetic")))
      r.fail(r.line_of("friction"),
             "give 'friction', or 'friction_static' and 'friction_kinetic', not both");
    const double both = r.number_or("friction", 0.0);
    require_range(r, "friction", both, 0.0, 0.0);
    c.friction_static = r.number_or("friction_static", r.number_or("friction_kinetic", both));
    require_range(r, "friction_static", c.friction_static, 0.0, 0.0);
    c.friction_kinetic = r.number_or("friction_kinetic", c.friction_static);
    require_range(r, "friction_kinetic", c.friction_kinetic, 0.0, 0.0);
    require_friction_order(r, c.friction_static, c.friction_kinetic);
    r.finish();
    scene.contacts.push_back(c);
  }
  refuse_body_overlaps(root, scene);
}

void read_springs(TomlReader& root, Scene& scene, const BodyNames& names) {
  for (const toml::table* t : root.tables("spring")) {
    TomlReader r = sub_reader(root, *t, "[[spring]]");
    Spring s;
    s.line = r.line();
    bool unused = false;
    const auto [a, b] = read_pair(r, names, false, unused);
    s.body_a = a;
    s.body_b = b;
    s.stiffness = r.number("stiffness");
    require_range(r, "stiffness", s.stiffness, 0.0, kMostSpringConstant, false);
    s.damping = r.number_or("damping", 0.0);
    require_range(r, "damping", s.damping, 0.0, kMostSpringConstant);
    s.rest_length =
        r.number_or("rest_length", (scene.bodies[a].position - scene.bodies[b].position).norm());
    require_range(r, "rest_length", s.rest_length, 0.0, kMostSize);
    r.finish();
    scene.springs.push_back(s);
  }
}

void read_hinges(TomlReader& root, Scene& scene, const BodyNames& names) {
  for (const toml::table* t : root.tables("hinge")) {
    TomlReader r = sub_reader(root, *t, "[[hinge]]");
    Hinge h;
    h.line = r.line();
    const std::string body = r.string("body");
    h.body = require_body(r, names, body, r.line_of("body"));
    if (scene.bodies[h.body].fixed)
      r.fail(r.line_of("body"), "[[hinge]] on body '" + body + "', which is fixed and cannot turn");
    h.anchor = r.vec3("anchor");
    require_planar(r, scene, "anchor", h.anchor);
    require_vector_range(r, "anchor", h.anchor, VectorKind::Position);
    const Vec3 axis = r.vec3_or("axis", h.axis);
    if (scene.dims == 2 && (axis.x() != 0.0 || axis.y() != 0.0))
      r.fail(r.line_of("axis"), "in a 2D case a hinge turns about z: 'axis' must be [0, 0, 1]");
    h.axis = unit_vector(r, "axis", axis);
    r.finish();
    scene.hinges.push_back(h);
  }
}

}  // namespace bb::load
