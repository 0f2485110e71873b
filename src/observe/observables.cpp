#include "observe/observables.hpp"

#include <algorithm>
#include <cmath>

#include "observe/observable_registry.hpp"
#include "physics/terminal_fall.hpp"

namespace bb {

ObservableValue terminal_speed(const Scene& scene, const Body& body) {
  const std::string does_not_apply = "does not apply: " + body.name;
  if (body.fixed) return {std::nullopt, does_not_apply + " is fixed"};
  if (!scene.air || scene.air->density <= 0.0)
    return {std::nullopt, does_not_apply + " is not in air"};
  // Where the force model's forces hold it against gravity (physics/terminal_fall.hpp).
  std::string why;
  const auto fall = terminal_fall(scene, static_cast<int>(&body - scene.bodies.data()), &why);
  if (!fall) return {std::nullopt, "does not apply: " + why};
  return {fall->speed, ""};
}

ObservableValue sag(const Scene& scene, const State& state) {
  if (!scene.grid) return {std::nullopt, "does not apply: the case has no [grid]"};
  const double g = scene.gravity.norm();
  if (g <= 0.0) return {std::nullopt, "does not apply: the case has no gravity"};
  // Heights along -gravity; rows are the grid's j index (its first row is the top row).
  const Vec3 up = -scene.gravity / g;
  const std::vector<int>& size = scene.grid->size;
  const int nx = size[0], ny = size[1], nz = size.size() > 2 ? size[2] : 1;
  const int first = scene.grid->first_body;
  double top = 0.0, bottom = 0.0;
  for (int k = 0; k < nz; ++k)
    for (int i = 0; i < nx; ++i) {
      top += state[first + k * ny * nx + i].position.dot(up);
      bottom += state[first + (k * ny + ny - 1) * nx + i].position.dot(up);
    }
  return {(top - bottom) / (nx * nz), ""};
}

ObservableValue final_shear(const Scene& scene, const State& start, const State& end) {
  if (!scene.grid) return {std::nullopt, "does not apply: the case has no [grid]"};
  const std::vector<int>& size = scene.grid->size;
  const int nx = size[0], ny = size[1], nz = size.size() > 2 ? size[2] : 1;
  if (nx < 2 || ny < 2) return {std::nullopt, "does not apply: the grid has no cells"};
  const int first = scene.grid->first_body;
  const auto at = [&](int i, int j, int k) { return first + (k * ny + j) * nx + i; };
  // Both diagonals of every cell in every layer: a sheared cell lengthens one, shortens
  // the other, whatever springs it has.
  double worst = 0.0;
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j + 1 < ny; ++j)
      for (int i = 0; i + 1 < nx; ++i)
        for (const auto& [a, b] : {std::pair{at(i, j, k), at(i + 1, j + 1, k)},
                                   std::pair{at(i + 1, j, k), at(i, j + 1, k)}}) {
          const double rest = (start[a].position - start[b].position).norm();
          const double now = (end[a].position - end[b].position).norm();
          if (rest > 0.0) worst = std::max(worst, std::abs(now - rest) / rest);
        }
  return {worst, ""};
}

ObservableValue final_height(const Scene& scene, int body, const State& state) {
  const double g = scene.gravity.norm();
  if (g <= 0.0) return {std::nullopt, "does not apply: the case has no gravity"};
  const Vec3 up = -scene.gravity / g;
  return {state[body].position.dot(up), ""};
}

ObservableValue terminal_time(const Scene& scene, int body, const Trajectory& trajectory) {
  const ObservableValue theory = terminal_speed(scene, scene.bodies[body]);
  if (!theory.value) return theory;
  const double target = kTerminalFraction * *theory.value;
  const auto speed = [&](std::size_t j) {
    return (trajectory.states[j][body].velocity - scene.air->wind).norm();
  };
  if (speed(0) >= target) return {trajectory.times[0], ""};
  for (std::size_t j = 1; j < trajectory.states.size(); ++j) {
    const double before = speed(j - 1), now = speed(j);
    if (now < target) continue;
    // A straight line between the two samples around the crossing.
    const double f = (target - before) / (now - before);
    return {trajectory.times[j - 1] + f * (trajectory.times[j] - trajectory.times[j - 1]), ""};
  }
  return {std::nullopt, "never reached 95 % of its terminal speed in the run"};
}

std::optional<double> terminal_velocity_formula(const Scene& scene, const Observe& observe) {
  return terminal_speed(scene, scene.bodies[observe.body]).value;
}

ObservableValue measure_final_speed(const Scene&, const Observe& observe,
                                    const Trajectory& trajectory, const EventTrace*) {
  return {trajectory.states.back()[observe.body].velocity.norm(), ""};
}

ObservableValue measure_terminal_velocity(const Scene& scene, const Observe& observe,
                                          const Trajectory& trajectory, const EventTrace*) {
  const ObservableValue theory = terminal_speed(scene, scene.bodies[observe.body]);
  if (!theory.value) return theory;
  // The drag acts on the velocity relative to the air, so that speed tends to v_t.
  return {(trajectory.states.back()[observe.body].velocity - scene.air->wind).norm(), ""};
}

ObservableValue measure_terminal_time(const Scene& scene, const Observe& observe,
                                      const Trajectory& trajectory, const EventTrace*) {
  return terminal_time(scene, observe.body, trajectory);
}

ObservableValue measure_sag(const Scene& scene, const Observe&, const Trajectory& trajectory,
                            const EventTrace*) {
  return sag(scene, trajectory.states.back());
}

ObservableValue measure_final_shear(const Scene& scene, const Observe&,
                                    const Trajectory& trajectory, const EventTrace*) {
  return final_shear(scene, trajectory.states.front(), trajectory.states.back());
}

ObservableValue measure_final_height(const Scene& scene, const Observe& observe,
                                     const Trajectory& trajectory, const EventTrace*) {
  return final_height(scene, observe.body, trajectory.states.back());
}

std::optional<double> formula_value(const Scene& scene, const Observe& observe) {
  const ObservableKind* m = observable_kind(observe.kind);
  if (m == nullptr || m->formula == nullptr) return std::nullopt;
  return m->formula(scene, observe);
}

ObservableValue measure(const Scene& scene, const Observe& observe, const Trajectory& trajectory,
                        const EventTrace* reference) {
  if (trajectory.states.empty()) return {std::nullopt, "no samples"};
  const ObservableKind* m = observable_kind(observe.kind);
  if (m == nullptr)
    return {std::nullopt,
            "kind '" + observe.kind + "' is not measured by this version of beachball"};
  return m->measure(scene, observe, trajectory, reference);
}

}  // namespace bb
