// The registry of observables: one row per kind of the case format, saying what the kind is
// (whether it describes the whole scene, whether it counts events), what it needs watched as
// a run goes, and how it is measured. A new observable is one file in observe/ (its
// MeasureFn, and for a kind that watches a level its CrossingFn) plus one row in
// observable_registry.cpp; the loader, the per-step observer, the
// reference and the report all read this table, and nothing matches kinds by name elsewhere.
#pragma once

#include <string>
#include <vector>

#include "observe/observable_measure.hpp"
#include "study/case_vocabulary.hpp"

namespace bb {

/// What an observable kind needs as a run goes, beyond the samples: the per-step observer
/// (observe/step_observer.hpp) and the reference's events set up only what is asked for,
/// and the report draws a panel for it. Flags, combined with |.
enum ObservableNeed : unsigned {
  kNeedsNothing = 0,
  kWatchesSwings = 1u << 0,   ///< the turns of a swing (a period): its velocity through zero
  kWatchesStops = 1u << 1,    ///< the end of each motion along the ground
  kWatchesFalls = 1u << 2,    ///< the centre reaching the fallen height above the ground
  kWatchesStretch = 1u << 3,  ///< every spring's largest stretch, between the steps too
  kWatchesOverlap = 1u << 4,  ///< the deepest overlap of the body's contacts
  kDrawsRotation = 1u << 5,   ///< the body's turn and spin get the rotation panel
  /// Measured from what was watched at every step (events, turns, peaks), not from the
  /// samples alone: a trajectory with rows at the samples only has no value for it.
  kReadsSteps = 1u << 6,
};

/// One kind of observable.
struct ObservableKind {
  std::string name;
  MeasureFn measure = nullptr;
  bool scene_wide = false;  ///< no `body`: named by its kind alone (max_stretch, sag)
  bool counted = false;     ///< takes an `n` (the n-th bounce)
  unsigned needs = kNeedsNothing;
  FormulaFn formula = nullptr;  ///< null: compared with the reference's own measurement
  bool rest_speed = false;      ///< takes a `rest_speed`: below it the body is at rest
  bool axis = false;            ///< signed about an `axis` (z in 2D)
  /// The value whose zero crossings it watches as events (located by the reference, found
  /// at every step by the per-step observer into EventTrace::crossings), or null.
  CrossingFn crossing = nullptr;
  bool level = false;  ///< takes a `level` (m): the height its crossings are of
};

/// Every observable kind, in the order of docs/observables.md.
const std::vector<ObservableKind>& observable_kind_table();

/// The kind `name`, or nullptr for a kind this version does not know.
const ObservableKind* observable_kind(const std::string& name);

/// Every observable kind's name ("final_speed", "terminal_velocity", ...).
std::vector<std::string> observable_kinds();

/// Whether `kind` needs `need` (an ObservableNeed); false for an unknown kind.
bool observable_needs(const std::string& kind, unsigned need);

/// The kinds as the case loader takes them.
CaseVocabulary case_vocabulary();

}  // namespace bb
