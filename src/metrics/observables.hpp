// Case-specific quantities ([[observe]]) measured on one trajectory.
#pragma once

#include <optional>
#include <string>

#include "metrics/trajectory.hpp"
#include "scene/scene.hpp"

namespace bb {

/// A measured value, or the reason there is none for this run.
struct ObservableValue {
  std::optional<double> value;
  std::string note;  ///< why `value` is empty
};

/// The observable's value on one run:
/// - final_speed: |v| at the end of the run (m/s);
/// - terminal_velocity: |v - wind| at the end of the run (m/s), the speed relative to the
///   air that tends to the terminal speed; a note where the terminal speed does not apply;
/// - terminal_time: when that speed first reaches 95 % of the terminal speed (s);
/// - final_shear: the grid's largest relative change of a cell diagonal, start to end;
/// - final_height: the centre's height along -gravity at the end of the run (m);
/// - sag: how far the grid's last row hangs below its first at the end (m, along gravity);
/// - the event kinds (bounces, contacts, period, max_stretch): see event_observables.hpp;
/// - the kinds of a sliding body (stop_time, stop_distance, rest_creep, final_velocity):
///   see stop_observables.hpp; rest_creep counts from the reference's stop, in the events
///   `reference` (nullptr: none);
/// - flips, how often a body turned over about its middle axis: see rotation_observables.hpp.
ObservableValue measure(const Scene& scene, const Observe& observe, const Trajectory& trajectory,
                        const EventTrace* reference);

/// The sag of the scene's grid at `state`: the mean height of its first row (j = 0, the
/// anchored row of a cloth) less that of its last row, heights along -gravity (m).
ObservableValue sag(const Scene& scene, const State& state);

/// How far the scene's grid has lost its shape at `end`: the largest relative change, from
/// `start`, of the length of either diagonal of any cell (a cell sheared by an angle gamma
/// changes its diagonals by about gamma / 2), whatever springs the cells have.
ObservableValue final_shear(const Scene& scene, const State& start, const State& end);

/// The height of `body`'s centre at `state` along -gravity, from the world's origin (m): a
/// throw's end point, where a force across the path (Magnus) lifted it or pushed it down.
ObservableValue final_height(const Scene& scene, int body, const State& state);

/// The terminal speed of `body`, sqrt(2 m |g| / (rho Cd A)) with A = pi r^2 (m/s), or a
/// note saying why it does not apply (no drag, no air, no gravity, or a Magnus force).
ObservableValue terminal_speed(const Scene& scene, const Body& body);

/// How close to its terminal speed a body must come for terminal_time: 95 %.
inline constexpr double kTerminalFraction = 0.95;

/// The first time `body`'s speed relative to the air reaches kTerminalFraction of its
/// terminal speed (s), placed by a straight line between the two samples around it (every
/// backend's samples lie on one grid, so each is measured alike); a note when it never does
/// or when the terminal speed does not apply.
ObservableValue terminal_time(const Scene& scene, int body, const Trajectory& trajectory);

/// What every run's value of `observe` is compared with when a formula gives it from the
/// scene alone (terminal_velocity: terminal_speed); nullopt when the comparison is with the
/// reference run's own measurement, as for every other kind.
std::optional<double> formula_value(const Scene& scene, const Observe& observe);

}  // namespace bb
