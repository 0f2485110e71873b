// [[impulse]]: instantaneous pushes at given times.
#include <algorithm>
#include <cmath>
#include <sstream>

#include "model/text.hpp"
#include "study/load_parts.hpp"

namespace bb::load {

void read_impulses(TomlReader& root, Scene& scene, const BodyNames& names) {
  for (const toml::table* t : root.tables("impulse")) {
    TomlReader r = sub_reader(root, *t, "[[impulse]]");
    Impulse imp;
    imp.line = r.line();
    const std::string body = r.string("body");
    imp.body = require_body(r, names, body, r.line_of("body"));
    if (scene.bodies[imp.body].fixed)
      r.fail(r.line_of("body"), "[[impulse]] on body '" + body + "', which is fixed");
    imp.time = r.number("time");
    require_range(r, "time", imp.time, 0.0, scene.duration);
    // Every backend must be able to apply it at the start of one of its own steps.
    for (double step : scene.dt) {
      const double ratio = imp.time / step;
      if (std::abs(ratio - std::round(ratio)) > 1e-9 * std::max(1.0, ratio))
        r.fail(r.line_of("time"), "'time' " + show(imp.time) + " s is not a multiple of 'dt' " +
                                      show(step) +
                                      " s; every backend applies the impulse at "
                                      "the start of a step");
    }
    imp.impulse = r.vec3("impulse");
    require_planar(r, scene, "impulse", imp.impulse);
    require_vector_range(r, "impulse", imp.impulse, VectorKind::Impulse);
    // The push must leave the body at a speed the case format allows.
    const double mass = scene.bodies[imp.body].mass;
    const double kick = imp.impulse.stableNorm() / mass;
    const VectorLimit& fastest = vector_limit(VectorKind::Velocity);
    if (kick > fastest.most)
      r.fail(r.line_of("impulse"),
             "'impulse' of " + short_number(imp.impulse.stableNorm()) + " N s on body '" + body +
                 "' (" + short_number(mass) + " kg) changes its velocity by " + short_number(kick) +
                 " m/s; " + fastest.what + " is at most " + short_number(fastest.most) + " m/s");
    if (r.has("point")) {
      imp.point = r.vec3("point");
      require_planar(r, scene, "point", *imp.point);
      require_vector_range(r, "point", *imp.point, VectorKind::Position);
    }
    r.finish();
    scene.impulses.push_back(imp);
  }
  std::stable_sort(scene.impulses.begin(), scene.impulses.end(),
                   [](const Impulse& a, const Impulse& b) { return a.time < b.time; });
}

}  // namespace bb::load
