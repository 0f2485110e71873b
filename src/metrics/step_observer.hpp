// Watches a fixed-step run at every step and finds its contacts and apexes from the
// states alone, the way a viewer of the run would: a contact is a step where two things
// that are close stop approaching, an apex where a body stops rising. It also times the
// swings of bodies whose period is observed and finds the springs' largest stretch.
// A peak between two steps (an apex, a spring's stretch turning from growing to shrinking)
// is the peak of the cubic through the two steps' values and rates (Hermite's): fourth
// order in the step, so the measurement does not cap a method's order below four.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "contact/contact_pairs.hpp"
#include "scene/event_trace.hpp"
#include "scene/peaks.hpp"
#include "scene/scene.hpp"
#include "scene/state.hpp"

namespace bb {

/// The part of `v` along the scene's ground (all of it when there is no ground).
Vec3 along_ground(const Scene& scene, const Vec3& v);

class StepObserver {
 public:
  explicit StepObserver(const Scene& scene);
  /// The state at time t (seconds), after every step, starting with t = 0.
  void observe(double t, const State& state);
  const EventTrace& trace() const { return trace_; }
  /// False when the scene has nothing to touch, time, stop or stretch: observing costs
  /// nothing then.
  bool active() const {
    return !pairs_.empty() || !swinging_.empty() || !stopping_.empty() || !falling_.empty() ||
           watch_stretch_;
  }

 private:
  const Scene& scene_;
  std::vector<ContactPair> pairs_;
  std::vector<double> closing_;           ///< per pair: normal speed of approach at the last step
  std::vector<Eigen::Vector3d> normals_;  ///< per pair: the contact normal at the last step
  std::vector<bool> rising_;   ///< per body: moving away from the ground at the last step
  std::vector<bool> bounced_;  ///< per body: a contact happened since its last apex
  /// Zero crossings of the velocity of the bodies whose period is observed.
  void observe_swings(double t, const State& s);
  std::vector<int> swinging_;     ///< bodies with a period observable
  std::vector<Vec3> low_, high_;  ///< per swinging body: smallest and largest velocity seen
  /// The first stop of each body whose stop is observed: its velocity along the ground
  /// reaching zero (within a millionth of the fastest it slid, or of |g| dt) or turning
  /// back between two steps, the crossing placed by linear interpolation; at rest at the
  /// start and still after the first step, it stopped at t = 0.
  void observe_stops(double t, const State& s);
  std::vector<int> stopping_;    ///< bodies with stop_time, stop_distance or rest_creep
  std::vector<double> fastest_;  ///< per stopping body: m/s, fastest along the ground yet
  /// The first time each body whose fall is observed has its centre below fallen_height()
  /// above the ground, placed by linear interpolation between the two steps.
  void observe_falls(double t, const State& s);
  std::vector<int> falling_;    ///< bodies with fall_time
  bool watch_stretch_ = false;  ///< a max_stretch observable is asked for
  /// The largest stretch of every spring with a rest length, at and between the steps.
  void observe_stretch(double h, const State& s);
  std::vector<int> stretched_;         ///< the springs with a rest length
  std::vector<Stretch> last_stretch_;  ///< per spring in stretched_, at the last step
  State previous_;
  double previous_t_ = 0.0;
  bool first_ = true;
  EventTrace trace_;
};

}  // namespace bb
