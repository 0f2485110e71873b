#include "observe/observable_registry.hpp"

#include "observe/event_observables.hpp"
#include "observe/hinge_observables.hpp"
#include "observe/observables.hpp"
#include "observe/rotation_observables.hpp"
#include "observe/stop_observables.hpp"

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
ObservableValue measure_downwind_distance(const Scene&, const Observe&, const Trajectory&,
                                          const EventTrace*);
ObservableValue measure_wobble_period(const Scene&, const Observe&, const Trajectory&,
                                      const EventTrace*);
ObservableValue measure_wobble_amplitude(const Scene&, const Observe&, const Trajectory&,
                                         const EventTrace*);
ObservableValue measure_surface_fold(const Scene&, const Observe&, const Trajectory&,
                                     const EventTrace*);
ObservableValue measure_time_above(const Scene&, const Observe&, const Trajectory&,
                                   const EventTrace*);
double height_above_level(const World&, const Observe&, const BodyState&);

const std::vector<ObservableKind>& observable_kind_table() {
  // name, measure, scene-wide, counted, needs; the other fields by name
  static const std::vector<ObservableKind> kinds = {
      {"final_speed", measure_final_speed},
      {"max_speed", measure_max_speed},
      {.name = "terminal_velocity",
       .measure = measure_terminal_velocity,
       .formula = terminal_velocity_formula},
      {"terminal_time", measure_terminal_time},
      {.name = "stop_time",
       .measure = measure_stop_time,
       .needs = kReadsSteps,
       .event = WatchedEvent::Stops,
       .rest_speed = true},
      {.name = "stop_distance",
       .measure = measure_stop_distance,
       .needs = kReadsSteps,
       .event = WatchedEvent::Stops,
       .rest_speed = true},
      {.name = "rest_creep",
       .measure = measure_rest_creep,
       .needs = kReadsSteps,
       .event = WatchedEvent::Stops,
       .rest_speed = true},
      {"final_velocity", measure_final_velocity},
      {"bounce_apex", measure_bounce_apex, false, true, kReadsSteps},
      {"contact_time", measure_contact_time, false, true, kReadsSteps},
      {"post_velocity", measure_post_velocity, false, false, kReadsSteps},
      {"post_normal_velocity", measure_post_normal_velocity, false, false, kReadsSteps},
      {.name = "post_angular_velocity",
       .measure = measure_post_angular_velocity,
       .needs = kDrawsRotation | kReadsSteps,
       .axis = true},
      {.name = "period",
       .measure = measure_period,
       .needs = kReadsSteps,
       .event = WatchedEvent::Swings},
      {.name = "max_penetration",
       .measure = measure_max_penetration,
       .needs = kReadsSteps,
       .event = WatchedEvent::Overlap},
      {"final_angle", measure_final_angle, false, false, kDrawsRotation | kReadsSteps},
      {"momentum_change", measure_momentum_change, false, false, kReadsSteps},
      {"energy_change", measure_energy_change, false, false, kReadsSteps},
      {.name = "max_stretch",
       .measure = measure_max_stretch,
       .scene_wide = true,
       .needs = kReadsSteps,
       .event = WatchedEvent::Stretch},
      {"sag", measure_sag, true},
      {"flips", measure_flips, false, false, kDrawsRotation | kReadsSteps},
      {"angular_momentum_change", measure_angular_momentum_change, false, false, kReadsSteps},
      {.name = "fall_time",
       .measure = measure_fall_time,
       .needs = kReadsSteps,
       .event = WatchedEvent::Falls},
      {"hinge_force", measure_hinge_force},
      {"final_height", measure_final_height},
      {"final_shear", measure_final_shear, true},
      {"forward_speed", measure_forward_speed},
      {.name = "drift_angle", .measure = measure_drift_angle, .rest_speed = true},
      {"made_good_upwind", measure_made_good_upwind},
      {"downwind_distance", measure_downwind_distance},
      {"wobble_period", measure_wobble_period},
      {"wobble_amplitude", measure_wobble_amplitude},
      {"surface_fold", measure_surface_fold, true},
      {.name = "time_above",
       .measure = measure_time_above,
       .needs = kReadsSteps,
       .event = WatchedEvent::Crossing,
       .crossing = height_above_level,
       .level = true},
  };
  return kinds;
}

const ObservableKind* observable_kind(const std::string& name) {
  for (const ObservableKind& k : observable_kind_table())
    if (k.name == name) return &k;
  return nullptr;
}

std::vector<std::string> observable_kinds() {
  std::vector<std::string> names;
  for (const ObservableKind& k : observable_kind_table()) names.push_back(k.name);
  return names;
}

bool observable_needs(const std::string& kind, unsigned need) {
  const ObservableKind* k = observable_kind(kind);
  return k != nullptr && (k->needs & need) != 0;
}

CaseVocabulary case_vocabulary() {
  CaseVocabulary vocabulary;
  for (const ObservableKind& k : observable_kind_table())
    vocabulary.observables.push_back(
        {k.name, k.scene_wide, k.counted, k.rest_speed, k.axis, k.level});
  return vocabulary;
}

}  // namespace bb
