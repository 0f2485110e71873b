// [baseline] of a case file: how `check --baseline` tells a worse value from rounding.
#include "study/load_parts.hpp"

namespace bb::load {

void read_baseline(TomlReader& root, Scene& scene) {
  const toml::table* t = root.table("baseline");
  if (t == nullptr) return;
  TomlReader r = sub_reader(root, *t, "[baseline]");
  BaselineOptions& b = scene.baseline;
  b.tolerance = r.number_or("tolerance", b.tolerance);
  require_range(r, "tolerance", b.tolerance, 0.0, 0.0);
  b.floor = r.number_or("floor", b.floor);
  require_range(r, "floor", b.floor, 0.0, 0.0);
  r.finish();
}

}  // namespace bb::load
