#include "report/rotation_plot.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "observe/observable_registry.hpp"
#include "report/gnuplot.hpp"
#include "run/drawn_bodies.hpp"
#include "run/run_summary.hpp"

namespace bb {

namespace {

/// The body axis (0, 1, 2) closest to the body's initial spin.
int spin_axis(const Body& body) {
  const Vec3 local = (body.orientation.conjugate() * body.angular_velocity).cwiseAbs();
  Eigen::Index axis = 2;
  if (local.norm() > 0.0) local.maxCoeff(&axis);
  return static_cast<int>(axis);
}

/// The two series of `body` in one run, whose states hold it at `slot`: angle (degrees)
/// and angular velocity (rad/s).
void series(const Scene& scene, int body, std::size_t slot, const Trajectory& t,
            std::vector<double>& angle, std::vector<double>& rate) {
  const int axis = spin_axis(scene.bodies[body]);
  Vec3 unit = Vec3::Zero();
  unit[axis] = 1.0;
  const Vec3 start = t.states.front()[slot].orientation * unit;
  for (const State& s : t.states) {
    const BodyState& b = s[slot];
    if (scene.dims == 2) {
      // Unwrapped at every step from the spin, by the runner: no sawtooth at each turn.
      angle.push_back(b.turn * 180.0 / std::numbers::pi);
      rate.push_back(b.angular_velocity.z());
    } else {
      const double c = std::clamp((b.orientation * unit).dot(start), -1.0, 1.0);
      angle.push_back(std::acos(c) * 180.0 / std::numbers::pi);
      rate.push_back((b.orientation.conjugate() * b.angular_velocity)[axis]);
    }
  }
}

}  // namespace

std::vector<int> turning_bodies(const Scene& scene) {
  std::vector<int> out;
  for (std::size_t i = 0; i < scene.bodies.size() && i < kPlottedBodies; ++i) {
    const Body& b = scene.bodies[i];
    // A body whose turning the case observes: its flips, its spin after a hit, its angle.
    const bool flips =
        std::any_of(scene.observes.begin(), scene.observes.end(), [&](const Observe& o) {
          return o.body == static_cast<int>(i) && observable_needs(o.kind, kDrawsRotation);
        });
    const bool hinged = std::any_of(scene.hinges.begin(), scene.hinges.end(),
                                    [&](const Hinge& h) { return h.body == static_cast<int>(i); });
    if (flips || hinged || (b.shape == Shape::Box && !b.fixed && b.angular_velocity.norm() > 0.0))
      out.push_back(static_cast<int>(i));
  }
  return out;
}

std::string rotation_plot(const CaseResults& results, FileBatch& batch, const std::string& name) {
  const Scene& scene = *results.scene;
  const std::vector<int> bodies = turning_bodies(scene);
  if (bodies.empty()) return "no body turns";
  const auto runs = report_runs(results);
  TwoColumnPlot plot(scene.name + ": angle and angular velocity at report_dt");
  const std::vector<int> drawn = drawn_bodies(scene);
  for (int b : bodies) {
    // Where the body sits in the kept states (drawn_bodies.hpp).
    const std::optional<std::size_t> slot = drawn_slot(drawn, b);
    if (!slot) continue;
    for (std::size_t i = 0; i < runs.size(); ++i) {
      const Trajectory& t = runs[i]->trajectory;
      if (t.states.empty()) continue;
      std::vector<double> angle, rate;
      series(scene, b, *slot, t, angle, rate);
      plot.add(false, i, runs[i]->backend, t.times, angle);
      plot.add(true, i, runs[i]->backend, t.times, rate);
    }
    const std::string& who = scene.bodies[b].name;
    plot.end_row(
        scene.dims == 2 ? who + ": angle about z (deg)" : who + ": tilt of its spin axis (deg)",
        scene.dims == 2 ? who + ": angular velocity (rad/s)"
                        : who + ": spin about that axis (rad/s)");
  }
  return plot.draw_into(batch, name);
}

}  // namespace bb
