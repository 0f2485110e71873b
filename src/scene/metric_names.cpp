#include "scene/metric_names.hpp"

#include <algorithm>

namespace bb {

const std::vector<std::string>& error_metric_names() {
  static const std::vector<std::string> v = {"position_max", "position_rms", "position_final",
                                             "velocity_max", "energy_max"};
  return v;
}

const std::vector<ObservableKind>& observable_kind_table() {
  static const std::vector<ObservableKind> kinds = {
      {"final_speed"},
      {"max_speed"},
      {"terminal_velocity"},
      {"terminal_time"},
      {"stop_time", false, false, kWatchesStops},
      {"stop_distance", false, false, kWatchesStops},
      {"rest_creep", false, false, kWatchesStops},
      {"final_velocity"},
      {"bounce_apex", false, true},
      {"contact_time", false, true},
      {"post_velocity"},
      {"post_normal_velocity"},
      {"post_angular_velocity", false, false, kDrawsRotation},
      {"period", false, false, kWatchesSwings},
      {"max_penetration", false, false, kWatchesOverlap},
      {"final_angle", false, false, kDrawsRotation},
      {"momentum_change"},
      {"energy_change"},
      {"max_stretch", true, false, kWatchesStretch},
      {"sag", true},
      {"flips", false, false, kDrawsRotation},
      {"angular_momentum_change"},
      {"fall_time", false, false, kWatchesFalls},
      {"hinge_force"},
      {"final_height"},
      {"final_shear", true},
      {"forward_speed"},
      {"drift_angle"},
      {"made_good_upwind"},
  };
  return kinds;
}

namespace {

const ObservableKind* find_kind(const std::string& name) {
  for (const ObservableKind& k : observable_kind_table())
    if (k.name == name) return &k;
  return nullptr;
}

}  // namespace

const std::vector<std::string>& observable_kinds() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> out;
    for (const ObservableKind& k : observable_kind_table()) out.push_back(k.name);
    return out;
  }();
  return names;
}

bool observable_is_scene_wide(const std::string& kind) {
  const ObservableKind* k = find_kind(kind);
  return k != nullptr && k->scene_wide;
}

bool observable_is_counted(const std::string& kind) {
  const ObservableKind* k = find_kind(kind);
  return k != nullptr && k->counted;
}

bool observable_needs(const std::string& kind, unsigned need) {
  const ObservableKind* k = find_kind(kind);
  return k != nullptr && (k->needs & need) != 0;
}

}  // namespace bb
