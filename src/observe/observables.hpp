// Case-specific quantities ([[observe]]) measured on one trajectory.
#pragma once

#include <optional>
#include <string>

#include "observe/observable_measure.hpp"

namespace bb {

/// The observable's value on one run, measured as its kind says (observable_registry.hpp;
/// the kinds and their units: docs/observables.md); a note where there is no value: no
/// samples, a kind this version does not measure, or the kind's own reason. `reference`
/// holds the reference's events where a kind measures from them (rest_creep), else nullptr.
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

/// The measurements of the kinds read from the samples (final_speed, terminal_velocity,
/// terminal_time, sag, final_shear, final_height), each a MeasureFn.
ObservableValue measure_final_speed(const Scene&, const Observe&, const Trajectory&,
                                    const EventTrace*);
ObservableValue measure_terminal_velocity(const Scene&, const Observe&, const Trajectory&,
                                          const EventTrace*);
/// terminal_velocity's formula: the body's terminal speed where it applies.
std::optional<double> terminal_velocity_formula(const Scene&, const Observe&);
ObservableValue measure_terminal_time(const Scene&, const Observe&, const Trajectory&,
                                      const EventTrace*);
ObservableValue measure_sag(const Scene&, const Observe&, const Trajectory&, const EventTrace*);
ObservableValue measure_final_shear(const Scene&, const Observe&, const Trajectory&,
                                    const EventTrace*);
ObservableValue measure_final_height(const Scene&, const Observe&, const Trajectory&,
                                     const EventTrace*);

}  // namespace bb
