#include "observe/rotation_observables.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <numbers>

#include "model/text.hpp"
#include "observe/event_observables.hpp"

namespace bb {

namespace {

/// The turn about z from the start to the end (degrees), as the runner unwrapped it at
/// every step from the spin (BodyState::turn).
ObservableValue final_angle(const Scene& scene, int body, const Trajectory& t) {
  if (scene.dims != 2) return {std::nullopt, "measured in 2D cases only (the turn about z)"};
  if (const std::optional<double> at = t.events.bodies[body].turn_unclear)
    return {std::nullopt, "its whole turns cannot be counted from t = " + short_number(*at) +
                              " s: its orientation moved more than a quarter turn away from what "
                              "its spin turns it by in a step (an orientation update that lags a "
                              "fast spin)"};
  const double turned = t.states.back()[body].turn - t.states.front()[body].turn;
  return {turned * 180.0 / std::numbers::pi, ""};
}

/// The spin (rad/s) about `axis` at the first sample after the body's first push or contact.
ObservableValue post_spin(const Scene& scene, int body, const Vec3& axis, const Trajectory& t) {
  std::optional<double> hit;
  for (const Impulse& i : scene.impulses)
    if (i.body == body) hit = std::min(hit.value_or(i.time), i.time);
  const BodyEvents& e = t.events.bodies[body];
  if (!e.contact_times.empty())
    hit = std::min(hit.value_or(e.contact_times[0]), e.contact_times[0]);
  if (!hit && e.unresolved_contact)
    return {std::nullopt, *unmeasured_contact(scene, body, e, false)};
  if (!hit) return {std::nullopt, "the body was neither pushed nor touched anything"};
  for (std::size_t j = 0; j < t.times.size(); ++j)
    if (t.times[j] > *hit) return {t.states[j][body].angular_velocity.dot(axis), ""};
  return {std::nullopt, "no sample after the first hit"};
}

}  // namespace

ObservableValue measure_final_angle(const Scene& scene, const Observe& observe,
                                    const Trajectory& trajectory, const EventTrace*) {
  return final_angle(scene, observe.body, trajectory);
}

ObservableValue measure_post_angular_velocity(const Scene& scene, const Observe& observe,
                                              const Trajectory& trajectory, const EventTrace*) {
  return post_spin(scene, observe.body, observe.axis, trajectory);
}

ObservableValue measure_flips(const Scene& scene, const Observe& observe,
                              const Trajectory& trajectory, const EventTrace*) {
  const Body& body = scene.bodies[observe.body];
  const Vec3 principal = principal_inertia(body);
  // The middle axis: neither the largest nor the smallest moment, and distinct from both.
  Eigen::Index low = 0, high = 0;
  principal.minCoeff(&low);
  principal.maxCoeff(&high);
  const Eigen::Index middle = 3 - low - high;
  const double gap = 1e-9 * principal.maxCoeff();
  if (low == high || principal[middle] - principal[low] <= gap ||
      principal[high] - principal[middle] <= gap)
    return {std::nullopt,
            "does not apply: " + body.name + " has no distinct middle principal axis"};
  const BodyState& start = trajectory.states.front()[observe.body];
  const Eigen::Matrix3d r0 = start.orientation.toRotationMatrix();
  const Vec3 momentum = r0 * principal.asDiagonal() * r0.transpose() * start.angular_velocity;
  if (momentum.norm() == 0.0) return {0.0, ""};
  const Vec3 along = momentum.normalized();
  Vec3 axis = Vec3::Zero();
  axis[middle] = 1.0;
  // A flip takes the axis from one side to the other: from beyond cos = +0.5 to beyond
  // -0.5 against L (60 degrees either way), so a wobble about the perpendicular, as a box
  // settling into another axis makes, is not counted.
  int flips = 0, side = 0;
  for (const State& s : trajectory.states) {
    const double now = (s[observe.body].orientation * axis).dot(along);
    const int here = now > 0.5 ? 1 : now < -0.5 ? -1 : 0;
    if (here != 0 && side != 0 && here != side) ++flips;
    if (here != 0) side = here;
  }
  return {static_cast<double>(flips), ""};
}

}  // namespace bb
