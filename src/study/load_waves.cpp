// [waves]: the simplified Gerstner surface of seed section 10, expanded into point bodies
// w<i> that only the formula moves (World::waves says how).
#include <cmath>

#include "study/load_parts.hpp"
#include "study/wave_limits.hpp"

namespace bb::load {

void read_waves(TomlReader& root, Scene& scene, bool has_grid) {
  const toml::table* t = root.table("waves");
  if (t == nullptr) return;
  TomlReader r = sub_reader(root, *t, "[waves]");
  if (scene.dims != 2)
    r.fail(r.line(), "[waves] is a profile in the x-y plane: the case must have dims = 2");
  if (!scene.bodies.empty() || has_grid)
    r.fail(r.line(),
           "[waves] is a kinematic surface and stands alone: the case may have no "
           "[[body]] and no [grid] beside it");
  Waves w;
  w.line = r.line();
  w.amplitude = r.number("amplitude");
  require_range(r, "amplitude", w.amplitude, 0.0, 0.0);
  w.wavenumber = r.number("wavenumber");
  require_range(r, "wavenumber", w.wavenumber, 0.0, 0.0, false);
  w.speed = r.number_or("speed", 1.0);
  require_range(r, "speed", w.speed, 0.0, 0.0);
  w.points = r.integer("points");
  require_range(r, "points", w.points, 2.0, kMaxWavePoints);
  w.from = r.number("from");
  w.to = r.number("to");
  if (!(w.to > w.from)) r.fail(r.line_of("to"), "'to' must be greater than 'from'");
  require_vector_range(r, "from", {w.from, 0.0, 0.0}, VectorKind::Position);
  require_vector_range(r, "to", {w.to, 0.0, 0.0}, VectorKind::Position);
  w.level = r.number_or("level", 0.0);
  require_vector_range(r, "level", {0.0, w.level, 0.0}, VectorKind::Position);
  if (const WaveProblem p = wave_problem(w); !p.key.empty())
    r.fail(r.line_of(p.key), "'" + p.key + "' in [waves] " + p.problem);
  r.finish();
  w.first_body = static_cast<int>(scene.bodies.size());
  for (int i = 0; i < w.points; ++i) scene.bodies.push_back(wave_point(w, i));
  scene.waves = w;
}

}  // namespace bb::load
