#include "observe/stop_observables.hpp"

#include "model/text.hpp"
#include "observe/step_observer.hpp"

namespace bb {

namespace {

/// The run's position of `body` at time t, linear between the samples around it; the
/// run's own stop, when it falls between them before t, stands in for the earlier sample
/// (so the position tends to the stop's as t does: no jump where the two stops meet).
std::optional<Vec3> position_at(const Trajectory& run, int body, double t, const BodyEvents* stop) {
  const std::vector<double>& times = run.times;
  for (std::size_t j = 0; j + 1 < times.size(); ++j) {
    if (t > times[j + 1]) continue;
    double t0 = times[j];
    Vec3 a = run.states[j][body].position;
    if (stop && *stop->stop_time >= t0 && *stop->stop_time <= t)
      t0 = *stop->stop_time, a = stop->stop_position;
    const Vec3& b = run.states[j + 1][body].position;
    const double span = times[j + 1] - t0;
    return span > 0.0 ? Vec3(a + (t - t0) / span * (b - a)) : b;
  }
  return std::nullopt;
}

ObservableValue creep(const Scene& scene, int body, const Trajectory& run,
                      const EventTrace* reference) {
  if (reference == nullptr || static_cast<std::size_t>(body) >= reference->bodies.size())
    return {std::nullopt, "no reference stop to measure from"};
  const std::optional<double> stopped = reference->bodies[body].stop_time;
  if (!stopped) return {std::nullopt, "does not apply: the reference never stops the body"};
  // From the later stop: a run still finishing its own slide is not creeping yet.
  const BodyEvents& own = run.events.bodies[body];
  std::optional<Vec3> from;
  if (own.stop_time && *own.stop_time >= *stopped)
    from = own.stop_position;
  else
    from = position_at(run, body, *stopped, own.stop_time ? &own : nullptr);
  if (!from) return {std::nullopt, "the run ended before the reference's stop"};
  return {along_ground(scene, run.states.back()[body].position - *from).norm(), ""};
}

}  // namespace

std::optional<double> stated_rest_speed(const Scene& scene, int body) {
  for (const Observe& o : scene.observes)
    if (o.body == body && o.rest_speed) return o.rest_speed;
  return std::nullopt;
}

Vec3 sliding_direction(const Scene& scene, int body) {
  const Vec3 pushed = along_ground(scene, scene.bodies[body].velocity);
  if (pushed.norm() > 0.0) return pushed.normalized();
  for (const Impulse& i : scene.impulses)
    if (i.body == body && along_ground(scene, i.impulse).norm() > 0.0)
      return along_ground(scene, i.impulse).normalized();
  const Vec3 downhill = along_ground(scene, scene.gravity);
  if (scene.ground && downhill.norm() > 0.0) return downhill.normalized();
  return Vec3::UnitX();
}

ObservableValue measure_final_velocity(const Scene& scene, const Observe& observe,
                                       const Trajectory& trajectory, const EventTrace*) {
  return {
      trajectory.states.back()[observe.body].velocity.dot(sliding_direction(scene, observe.body)),
      ""};
}

ObservableValue measure_rest_creep(const Scene& scene, const Observe& observe,
                                   const Trajectory& trajectory, const EventTrace* reference) {
  return creep(scene, observe.body, trajectory, reference);
}

namespace {

/// The observed body's last stop, or the note saying why there is none.
std::optional<ObservableValue> no_stop(const Scene& scene, const Observe& observe,
                                       const Trajectory& trajectory) {
  if (static_cast<std::size_t>(observe.body) >= trajectory.events.bodies.size())
    return ObservableValue{std::nullopt, "the run has no event trace"};
  if (trajectory.events.bodies[observe.body].stop_time) return std::nullopt;
  const std::optional<double> rest = stated_rest_speed(scene, observe.body);
  return ObservableValue{
      std::nullopt,
      "never stops in the run: its last motion along the ground did not slow to its rest "
      "speed (" +
          (rest ? short_number(*rest) + " m/s, the case's 'rest_speed'"
                : std::string("a thousandth of the fastest it moved along the ground")) +
          ") or turn back"};
}

}  // namespace

ObservableValue measure_stop_time(const Scene& scene, const Observe& observe,
                                  const Trajectory& trajectory, const EventTrace*) {
  if (auto none = no_stop(scene, observe, trajectory)) return *none;
  return {*trajectory.events.bodies[observe.body].stop_time, ""};
}

ObservableValue measure_stop_distance(const Scene& scene, const Observe& observe,
                                      const Trajectory& trajectory, const EventTrace*) {
  if (auto none = no_stop(scene, observe, trajectory)) return *none;
  const BodyEvents& e = trajectory.events.bodies[observe.body];
  return {along_ground(scene, e.stop_position - e.motion_start).norm(), ""};
}

}  // namespace bb
