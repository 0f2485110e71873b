// Names of the error metrics and observable kinds results may carry.
#pragma once

#include <string>
#include <vector>

namespace bb {

/// position_max, position_rms, position_final, velocity_max, energy_max.
const std::vector<std::string>& error_metric_names();

/// What an observable kind needs as a run goes, beyond the samples: the per-step observer
/// (metrics/step_observer.hpp) and the reference's events set up only what is asked for,
/// and the report draws a panel for it. Flags, combined with |.
enum ObservableNeed : unsigned {
  kNeedsNothing = 0,
  kWatchesSwings = 1u << 0,   ///< the velocity's upward zero crossings (a period)
  kWatchesStops = 1u << 1,    ///< the end of each motion along the ground
  kWatchesFalls = 1u << 2,    ///< the centre reaching the fallen height above the ground
  kWatchesStretch = 1u << 3,  ///< every spring's largest stretch, between the steps too
  kWatchesOverlap = 1u << 4,  ///< the deepest overlap of the body's contacts
  kDrawsRotation = 1u << 5,   ///< the body's turn and spin get the rotation panel
};

/// One kind of observable as the case format knows it: its name, whether it describes the
/// whole scene (no `body`; named by its kind alone), whether it counts events (takes an `n`:
/// the n-th bounce) and what it needs watched. How it is measured: metrics/observable_kinds.
struct ObservableKind {
  std::string name;
  bool scene_wide = false;
  bool counted = false;
  unsigned needs = kNeedsNothing;
};

/// Every observable kind, in the order of docs/observables.md.
const std::vector<ObservableKind>& observable_kind_table();

/// Every observable kind's name ("final_speed", "terminal_velocity", ...).
const std::vector<std::string>& observable_kinds();

/// Whether observables of this kind describe the whole scene and take no `body` (they are
/// named by their kind alone): max_stretch, sag, final_shear.
bool observable_is_scene_wide(const std::string& kind);

/// Kinds that count events and take an `n` (the n-th bounce, contact, ...).
bool observable_is_counted(const std::string& kind);

/// Whether `kind` needs `need` (an ObservableNeed); false for an unknown kind.
bool observable_needs(const std::string& kind, unsigned need);

}  // namespace bb
