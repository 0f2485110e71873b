// Watches a fixed-step run at every step and finds its contacts and apexes from the
// states alone, the way a viewer of the run would: a contact is a step where two things
// that are close stop approaching, an apex where a body stops rising. It also times the
// swings of bodies whose period is observed and finds the springs' largest stretch.
// A peak between two steps (an apex, a spring's stretch turning from growing to shrinking)
// is the peak of the cubic through the two steps' values and rates (Hermite's): fourth
// order in the step, so the measurement does not cap a method's order below four.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <vector>

#include "contact/contact_pairs.hpp"
#include "model/peaks.hpp"
#include "model/state.hpp"
#include "observe/event_watches.hpp"
#include "seam/event_trace.hpp"
#include "study/scene.hpp"

namespace bb {

/// The part of `v` along the scene's ground (all of it when there is no ground).
Vec3 along_ground(const Scene& scene, const Vec3& v);

/// What a 2D body's spin turned it by (radians) over a step of `h` seconds from `before` to
/// `now` (the mean of the spins at its ends, times h), to count the whole turns of the step
/// by (next_turn). The spin, not the angles alone, says how many whole
/// turns the step made: right while the spin's estimate is within half a turn of the true
/// turn over the step, even where a step turns the body by more than half a turn. Where an
/// impulse changed the spin `kicked` seconds into the step, the body turned at the spin of
/// `before` until then and at that of `now` after (a mean would lose half of a kick's turn).
double spin_turn(const BodyState& before, const BodyState& now, double h,
                 std::optional<double> kicked = std::nullopt);
/// The unwrapped turn at the end of a step that began at `turn` and turned by about `spun`:
/// the angle of `now` plus the whole turns that bring it nearest to turn + spun.
double next_turn(double turn, double spun, const BodyState& now);

/// A step that takes this share of a pair's approach away at once pushes the pair apart as
/// a hit does, even before they overlap (an engine's contact begins within its margin).
inline constexpr double kHardPush = 0.1;

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
           !crossing_watches_.empty() || watch_stretch_ || watch_turns_;
  }
  /// Writes each body's turn about z (BodyState::turn) into `state`, the state observed
  /// last: unwrapped at every step for a body that can turn, its angle for one that cannot
  /// (2D scenes; in 3D the turn stays 0).
  void write_turns(State& state) const;

 private:
  const Scene& scene_;
  std::vector<ContactPair> pairs_;
  std::vector<double> closing_;           ///< per pair: normal speed of approach at the last step
  std::vector<Eigen::Vector3d> normals_;  ///< per pair: the contact normal at the last step
  std::vector<bool> rising_;   ///< per body: moving away from the ground at the last step
  std::vector<bool> bounced_;  ///< per body: a contact happened since its last apex
  /// Upward zero crossings of the velocity of the bodies whose period is observed, or, for
  /// a body on a hinge, of its spin about the hinge's axis.
  void observe_swings(double t, const State& s);
  std::vector<int> swinging_;              ///< bodies with a period observable
  std::vector<const Hinge*> swing_hinge_;  ///< per swinging body: its hinge, or nullptr
  /// The stop of each body whose stop is observed: the end of its last motion along the
  /// ground (stop_observables.hpp). A motion begins at the start of the run when the body
  /// moves there, or where it sets off after two or more observations at rest (the start
  /// counts as two): at rest is slower than its rest speed (kRestShare), so an engine's
  /// wobble or creep at rest is no motion. It ends at the first step where its velocity
  /// along the ground comes to rest or turns back: where the speed along its direction
  /// reaches zero on the line through the two steps (at most a step past the later one, for
  /// a body that came to rest still creeping). A body at rest throughout stopped at t = 0.
  void observe_stops(double t, const State& s);
  /// Where a watched body is in its motions.
  struct StopWatch {
    bool moving = false;   ///< in a motion along the ground
    int resting = 0;       ///< observations at rest in a row
    double largest = 0.0;  ///< m/s, the fastest in any motion
    Vec3 begin;            ///< where the current motion began
  };
  std::vector<int> stopping_;    ///< bodies with stop_time, stop_distance or rest_creep
  std::vector<double> fastest_;  ///< per stopping body: m/s, fastest along the ground yet
  std::vector<std::optional<double>> rest_speeds_;  ///< per stopping body: the case's
  std::vector<StopWatch> watches_;                  ///< per stopping body
  /// The first time each body whose fall is observed has its centre below fallen_height()
  /// above the ground, placed by linear interpolation between the two steps.
  void observe_falls(double t, const State& s);
  std::vector<int> falling_;  ///< bodies with fall_time
  /// Each observe whose kind watches a crossing (a CrossingFn) and its value at the last
  /// step: a step where the value changes sign is a crossing, placed by linear
  /// interpolation between the two steps.
  struct CrossingState {
    CrossingWatch watch;
    double last = 0.0;
  };
  void observe_crossings(double t, const State& s);
  std::vector<CrossingState> crossing_watches_;
  bool watch_stretch_ = false;  ///< a max_stretch observable is asked for
  /// Contacts between each pair that can touch (a step where they are close and stop
  /// approaching), their penetration, and the first collision's balance of momentum and
  /// energy.
  void observe_contacts(double t, double dt, const State& s);
  /// A contact from its hit to the last step that still pushes the pair apart: one step for
  /// a rigid engine's impulse, several for a soft contact (MuJoCo's), which goes on pushing
  /// after the pair stops approaching. The post-contact velocities and the first
  /// collision's balance are those at its end, the balance taken from the last step before
  /// the pair began to push (the last free step), so that it holds the whole contact.
  struct Episode {
    bool open = false;      ///< after its hit, while the pair still pushes
    bool balances = false;  ///< it writes the first collision's balance
    double event_time = 0.0;
    double start_time = 0.0;  ///< s, the last free step
    BodyState a0, b0;         ///< the pair's bodies at the last free step (a twice for the ground)
    Vec3 gravity_turn = Vec3::Zero();  ///< gravity's angular impulse since the last free step
  };
  std::vector<Episode> episodes_;  ///< per pair
  /// Per body: the pair whose open episode writes its post-contact velocity, or -1.
  std::vector<int> post_owner_;
  bool balance_open_ = false;  ///< the first collision's episode is still open
  /// Whether pair's episodes still matter: a body's first contact or the first collision
  /// between moving bodies not read yet, or still open.
  bool episode_watched(const ContactPair& pair) const;
  /// Writes episode k's values (post velocities, the balance) from the state at time t.
  void write_episode(std::size_t k, double t, const State& s);
  void close_episode(std::size_t k);
  /// Pair k, overlapping or pushed hard (kHardPush) at time t, slowed its approach to
  /// `closing` (m/s) without stopping: a contact seen only as a push
  /// (BodyEvents::unresolved_contact).
  void note_unresolved(std::size_t k, double t, double closing);
  /// Pair k hit at time t along `normal` (from b to a): each moving body's contact time, its
  /// first post-contact normal, and the episode opened (or kept) and written.
  void record_hit(std::size_t k, double t, const State& s, const Eigen::Vector3d& normal,
                  bool b_moves);
  /// Gravity's angular impulse (N m s) about the origin on bodies a and b over the step of
  /// dt seconds that ended in `s`, at the mid positions.
  Vec3 gravity_turn(const State& s, int a, int b, double dt) const;
  /// Apexes: a body that bounced stops rising above the ground.
  void observe_apexes(double dt, const State& s);
  /// The largest stretch of every spring with a rest length, at and between the steps.
  void observe_stretch(double h, const State& s);
  std::vector<int> stretched_;         ///< the springs with a rest length
  std::vector<Stretch> last_stretch_;  ///< per spring in stretched_, at the last step
  /// Per body: its turn about z is unwrapped at every step (a 2D body that can turn: it
  /// spins at the start, is pushed, touches something or hangs on a hinge).
  std::vector<char> turning_;
  bool watch_turns_ = false;
  std::vector<double> turns_;  ///< per body: radians, the turn about z so far
  /// The first impulse on body i in (previous_t_ - rounding, t): seconds into the step.
  std::optional<double> kick_in_step(std::size_t i, double t) const;
  State previous_;
  double previous_t_ = 0.0;
  bool first_ = true;
  EventTrace trace_;
};

}  // namespace bb
