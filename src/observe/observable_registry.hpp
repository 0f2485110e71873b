// The registry of observables: one row per kind of the case format, saying what the kind is
// (whether it describes the whole scene, whether it counts events), the event it watches as
// a run goes, and how it is measured. A new observable is one file in observe/ (its
// MeasureFn, and for a kind that watches a level its CrossingFn) plus one row in
// observable_registry.cpp; the loader, the per-step observer, the reference and the report
// all read this table (the events through event_watches.hpp's one switch), and nothing
// matches kinds by name elsewhere.
#pragma once

#include <string>
#include <vector>

#include "observe/observable_measure.hpp"
#include "study/case_vocabulary.hpp"

namespace bb {

/// The event an observable kind watches as a run goes, beyond the samples and the contacts
/// every run watches: the per-step observer (observe/step_observer.hpp) and the reference
/// set up only what is asked for, each kind's in the one switch of EventWatches::add
/// (observe/event_watches.hpp).
enum class WatchedEvent {
  None,      ///< nothing beyond the samples and the contacts
  Swings,    ///< the turns of a swing (a period): its velocity through zero
  Stops,     ///< the end of each motion along the ground
  Falls,     ///< the centre reaching the fallen height above the ground
  Stretch,   ///< every spring's largest stretch, between the steps too
  Overlap,   ///< the deepest overlap of the body's contacts
  Crossing,  ///< the kind's CrossingFn through zero, either way (time_above: a level)
};

/// What else an observable kind needs: the report draws a panel for it, or it reads every
/// step. Flags, combined with |.
enum ObservableNeed : unsigned {
  kNeedsNothing = 0,
  kDrawsRotation = 1u << 0,  ///< the body's turn and spin get the rotation panel
  /// Measured from what was watched at every step (events, turns, peaks), not from the
  /// samples alone: a trajectory with rows at the samples only has no value for it.
  kReadsSteps = 1u << 1,
};

/// One kind of observable.
struct ObservableKind {
  std::string name;
  MeasureFn measure = nullptr;
  bool scene_wide = false;  ///< no `body`: named by its kind alone (max_stretch, sag)
  bool counted = false;     ///< takes an `n` (the n-th bounce)
  unsigned needs = kNeedsNothing;
  WatchedEvent event = WatchedEvent::None;  ///< what it watches as a run goes
  FormulaFn formula = nullptr;              ///< null: compared with the reference's own measurement
  bool rest_speed = false;                  ///< takes a `rest_speed`: below it the body is at rest
  bool axis = false;                        ///< signed about an `axis` (z in 2D)
  /// The value whose zero crossings it watches (event Crossing: located by the reference,
  /// found at every step by the per-step observer into EventTrace::crossings), or null.
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
