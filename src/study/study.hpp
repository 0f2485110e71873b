// The study: how a world is examined. The run's length and steps, the course's variants, the
// engines' settings, what is observed, gated and claimed, the sweep, the report and the
// stability search.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "seam/engine_tables.hpp"
#include "seam/observes.hpp"

namespace bb {

/// Which of the course text's variants to run.
struct CourseOptions {
  std::vector<std::string> integrators;
  std::vector<std::string> ground;
  std::vector<std::string> friction;
  std::vector<std::string> hit;   ///< a ball against a moving box (section 5, the plank)
  std::vector<std::string> spin;  ///< a ball's spin at its contacts (section 5)
};

/// A CI accuracy gate, checked at report_dt.
struct Gate {
  std::string backend;
  std::string metric;
  double max = 0.0;
  int line = 0;
};

/// One side of a claim: `<backend or *>:<metric or observable>`, or a number.
struct ClaimSide {
  std::string backend;  ///< a backend of the case, or "*" (each backend in turn); "" for a number
  std::string metric;   ///< an error metric or an [[observe]] of the case
  double number = 0.0;  ///< when backend is ""
  bool is_number() const { return backend.empty(); }
};

/// What a run that diverged says about a claim ([[claim]] `diverged`).
enum class DivergedCounts {
  Nothing,  ///< named in the verdict, not judged (the default)
  Holds,    ///< evidence that the claim holds: a claim that something grows or explodes
  Fails,    ///< evidence against it: a claim that something stays bounded
};

/// A map's claim ([[claim]] with `region`): at each point of the map (two [[sweep]]s, one of
/// them the step), `backend`'s outcome is `inside` where the point's step lies inside the
/// region and `outside` where it lies beyond; a point whose step is within `margin` of the
/// region's boundary (relative) is not judged.
struct RegionClaim {
  std::string backend;
  /// "theory": the points whose value of the axis the map's theory bounds (the step, the
  /// ground's tilt) is below that theory's bound for the backend at the point, times
  /// `boundary_factor` (run/map_theory.hpp).
  std::string region;
  double boundary_factor = 1.0;
  std::string inside = "ok";         ///< "ok", "exploded" (past the onset or diverged), "any"
  std::string outside = "exploded";  ///< as `inside`
  double margin = 0.0;               ///< 0 to 1
};

/// A sentence of the course text checked by numbers ([[claim]]): left op right, or over a
/// map, a region's outcomes (`region`; then left, op and right are empty).
struct Claim {
  std::string text;
  std::string seed;  ///< the section of the course text, may be empty
  /// The course text's own words that the claim tests (line breaks and runs of spaces may
  /// differ); for a claim of the case's own, the words that prompted it, or "".
  std::string quote;
  /// The case's own claim, not the text's (`own = true`).
  bool own = false;
  ClaimSide left;
  std::string op;  ///< "<", "<=", ">", ">=", "~" (within `tolerance`)
  ClaimSide right;
  double tolerance = 0.0;  ///< absolute, in the quantities' unit; for "~"
  DivergedCounts diverged = DivergedCounts::Nothing;
  /// `compare = "error"`: each side is read as its distance from the reference's value,
  /// |x - x_reference| (an error metric is one already), not as the value itself.
  bool against_reference = false;
  std::optional<RegionClaim> region;
  int line = 0;
};

/// One parameter of the case varied over values ([[sweep]]): each value is a run of the
/// whole case for every backend at report_dt.
struct Sweep {
  std::string parameter;  ///< a path into the case, see sweep_parameter.hpp
  std::vector<double> values;
  /// What a published study found on this sweep, shown on the page (may be empty).
  std::string published;
  /// An observable whose first value above `onset_above` marks where something starts
  /// (the angle at which a block first slides); may be empty.
  std::string onset;
  double onset_above = 0.0;
  /// A map's colour: an error metric or observable whose error (its difference from the
  /// reference's) colours each ok point, on one scale for every backend; may be empty.
  std::string colour;
  int line = 0;
};

/// How the report presents the case ([report], optional).
struct ReportOptions {
  /// Error metrics or observable names to draw work-precision diagrams for.
  std::vector<std::string> metrics{"position_max"};
  /// Error to reach, in the first metric's unit, for the "cheapest dt" table.
  double target = 0.01;
};

/// How `beachball stability` searches ([stability], optional).
struct StabilityOptions {
  /// The energy's rise above its start (after the last impulse) compounds when, in each of
  /// the run's last two quarters, it grows more than this many times faster than steady
  /// drift would (a rise proportional to the elapsed time), without slowing down as any
  /// power of time does (metrics/energy_growth.hpp).
  double growth_factor = 1.02;
  double dt_min = 0.0;  ///< seconds; 0: a quarter of the case's smallest dt
  double dt_max = 0.0;  ///< seconds; 0: a sixteenth of the duration (16 steps a run)
};

/// How `check --baseline` compares a run with its kept results ([baseline], optional): a
/// value is worse when it grew past both the baseline times (1 + tolerance) and the
/// baseline plus floor (docs/ci.md says why these defaults).
struct BaselineOptions {
  double tolerance = 1e-3;  ///< relative
  double floor = 1e-9;      ///< absolute, in the metric's own unit
};

/// How the world is examined: the run's length and steps, the course's variants, the
/// engines' settings, what is observed, gated and claimed, the sweep, the report and the
/// stability search.
struct Study {
  std::string file;  ///< where it was loaded from, for messages
  /// The case's text as loaded, and what was changed in it (a sweep's point, "" for none):
  /// together they decide every run, and a kept result's key is made of them. A scene made
  /// in code has no text, and its runs are never kept.
  std::string source;
  std::string variant;
  std::string name;
  std::string title;
  std::string seed;        ///< section of the course text, may be empty
  double duration = 0.0;   ///< simulated seconds
  double sample = 0.0;     ///< seconds between samples
  std::vector<double> dt;  ///< fixed steps to sweep, seconds
  double report_dt = 0.0;  ///< the game-frame step for tables and gates
  CourseOptions course;
  EngineTables engines;
  std::vector<Observe> observes;
  std::vector<Gate> gates;
  std::vector<Claim> claims;
  std::optional<Sweep> sweep;
  /// A second [[sweep]]: with it the two make a map, the case run at every value of `sweep`
  /// with every value of this one (sweep_runner.hpp); it may be the step, "dt".
  std::optional<Sweep> second_sweep;
  ReportOptions report;
  StabilityOptions stability;
  BaselineOptions baseline;

  /// Number of samples after t = 0 (duration / sample).
  int sample_count() const;
  /// Steps of size `dt` between two samples (sample / dt).
  int steps_per_sample(double dt) const;
};

}  // namespace bb
