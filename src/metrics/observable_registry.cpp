#include "metrics/observable_registry.hpp"

#include <map>

#include "metrics/event_observables.hpp"
#include "metrics/hinge_observables.hpp"
#include "metrics/observables.hpp"
#include "metrics/rotation_observables.hpp"
#include "metrics/stop_observables.hpp"

namespace bb {

// Kinds measured in a file of their own.
ObservableValue measure_max_speed(const Scene&, const Observe&, const Trajectory&,
                                  const EventTrace*);
ObservableValue measure_forward_speed(const Scene&, const Observe&, const Trajectory&,
                                      const EventTrace*);
ObservableValue measure_drift_angle(const Scene&, const Observe&, const Trajectory&,
                                    const EventTrace*);
ObservableValue measure_made_good_upwind(const Scene&, const Observe&, const Trajectory&,
                                         const EventTrace*);

const ObservableMeasure* observable_measure(const std::string& kind) {
  static const std::map<std::string, ObservableMeasure> registry = {
      {"final_speed", {measure_final_speed}},
      {"max_speed", {measure_max_speed}},
      {"terminal_velocity", {measure_terminal_velocity, terminal_velocity_formula}},
      {"terminal_time", {measure_terminal_time}},
      {"stop_time", {measure_stop_time}},
      {"stop_distance", {measure_stop_distance}},
      {"rest_creep", {measure_rest_creep}},
      {"final_velocity", {measure_final_velocity}},
      {"bounce_apex", {measure_bounce_apex}},
      {"contact_time", {measure_contact_time}},
      {"post_velocity", {measure_post_velocity}},
      {"post_normal_velocity", {measure_post_normal_velocity}},
      {"post_angular_velocity", {measure_post_angular_velocity}},
      {"period", {measure_period}},
      {"max_penetration", {measure_max_penetration}},
      {"final_angle", {measure_final_angle}},
      {"momentum_change", {measure_momentum_change}},
      {"energy_change", {measure_energy_change}},
      {"max_stretch", {measure_max_stretch}},
      {"sag", {measure_sag}},
      {"flips", {measure_flips}},
      {"angular_momentum_change", {measure_angular_momentum_change}},
      {"fall_time", {measure_fall_time}},
      {"hinge_force", {measure_hinge_force}},
      {"final_height", {measure_final_height}},
      {"final_shear", {measure_final_shear}},
      {"forward_speed", {measure_forward_speed}},
      {"drift_angle", {measure_drift_angle}},
      {"made_good_upwind", {measure_made_good_upwind}},
  };
  const auto found = registry.find(kind);
  return found == registry.end() ? nullptr : &found->second;
}

}  // namespace bb
