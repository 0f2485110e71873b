#include "scene/metric_names.hpp"

#include <algorithm>

namespace bb {

const std::vector<std::string>& error_metric_names() {
  static const std::vector<std::string> v = {"position_max", "position_rms", "position_final",
                                             "velocity_max", "energy_max"};
  return v;
}

const std::vector<std::string>& observable_kinds() {
  static const std::vector<std::string> v = {"final_speed",
                                             "terminal_velocity",
                                             "terminal_time",
                                             "stop_time",
                                             "stop_distance",
                                             "rest_creep",
                                             "final_velocity",
                                             "bounce_apex",
                                             "contact_time",
                                             "post_velocity",
                                             "post_normal_velocity",
                                             "post_angular_velocity",
                                             "period",
                                             "max_penetration",
                                             "final_angle",
                                             "momentum_change",
                                             "energy_change",
                                             "max_stretch",
                                             "sag",
                                             "flips",
                                             "angular_momentum_change",
                                             "fall_time",
                                             "hinge_force",
                                             "final_height",
                                             "final_shear"};
  return v;
}

bool observable_is_scene_wide(const std::string& kind) {
  return kind == "max_stretch" || kind == "sag" || kind == "final_shear";
}

bool observable_is_counted(const std::string& kind) {
  return kind == "bounce_apex" || kind == "contact_time";
}

}  // namespace bb
