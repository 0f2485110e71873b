// The scene as a hybrid system for the reference: rigid bodies in free flight between
// contacts, each contact an event resolved by Newton's restitution along the normal; a body
// resting on a ground with friction sticks or slides by Coulomb's law (sliding_modes.hpp),
// each stop an event.
#pragma once

#include <Eigen/Geometry>
#include <stdexcept>
#include <string>
#include <vector>

#include "contact/contact_pairs.hpp"
#include "model/state.hpp"
#include "observe/observable_measure.hpp"
#include "physics/force_model.hpp"
#include "reference/hybrid_integrator.hpp"
#include "reference/sliding_modes.hpp"
#include "seam/backend.hpp"
#include "seam/event_trace.hpp"
#include "study/start_case.hpp"

namespace bb {

/// Thrown when a scene reaches a configuration the reference cannot resolve exactly
/// (several simultaneous contacts on one body, a body resting under another).
struct BeyondExactAnswer : UnsupportedScene {
  using UnsupportedScene::UnsupportedScene;
};

class SceneModel : public HybridModel {
 public:
  /// Values per body in the integrated state: position, velocity, orientation (w, x, y, z),
  /// angular velocity in the body's own frame (read() turns it into the world's).
  static constexpr std::size_t kPerBody = 13;

  /// The world's model; `settings` name the observes whose events it locates and the sample
  /// interval (none and 0 when not given: no observed events, no rest below a bounce).
  explicit SceneModel(const World& world, const BackendSettings& settings = {});
  /// The model of a case's world, told its study's settings.
  explicit SceneModel(const Scene& scene) : SceneModel(scene, backend_settings(scene)) {}
  /// The integrated state at t = 0.
  std::vector<double> initial_state() const;
  /// `y` as the runner's per-body state.
  void read(const double* y, State& out) const;

  std::size_t dimension() const override { return kPerBody * scene_.bodies.size(); }
  void derivatives(double t, const double* y, double* dydt) override;
  /// Analytic in position, velocity (drag, Magnus, the resting projection), orientation and
  /// Euler's torque-free equations; the Magnus force's dependence on the orientation (through
  /// the world's spin R(q) w) by central differences.
  void jacobian(double t, const double* y, double* dfdy, double* dfdt) override;
  /// A quarter of the time the fastest approach takes to cross the thinnest contact
  /// region (both bodies' thickness along the line of approach) of any pair not with the
  /// ground, so that no step jumps over a thin panel or a small ball.
  double max_step(double t, const double* y) override;
  std::size_t event_count() const override { return sources_.size(); }
  void events(double t, const double* y, double* g) override;
  void apply(std::size_t k, double t, double* y) override;

  /// One of the scene's [[impulse]] entries, at time t: velocity and spin change at once. A
  /// body resting on the ground that is pushed into it bounces off it there and then.
  void apply_impulse(const Impulse& impulse, double t, double* y);

  /// Contacts, apexes and the first collision's balance, each at its located time.
  const EventTrace& trace() const { return trace_; }
  /// A ground bounce whose rebound would keep the body off the ground for less than this
  /// many seconds leaves it resting on the ground instead (ending a geometric series of
  /// ever smaller bounces): a millionth of the sample interval.
  double rest_flight_time() const { return 1e-6 * settings_.sample; }
  /// Why the reference cannot answer this scene exactly, or "" when it can.
  static std::string beyond_exact_answer(const World& scene);

 private:
  /// What one event function watches, each kind of event resolved in one switch of
  /// events() and one of apply().
  enum class Watch {
    Contact,     ///< a contact pair's gap (a hinged box's corners for a landing)
    Apex,        ///< a body's velocity along the ground's normal after a bounce
    Swing,       ///< a zero crossing of one velocity component of a body whose period is observed
    HingeSwing,  ///< a hinged body's spin about its axis through zero upwards
    Stop,        ///< a sliding body's speed along its direction of sliding reaching zero
    Fall,        ///< the centre reaching fallen_height() above the ground
    Crossing,    ///< an observe's CrossingFn through zero (observable_registry.hpp)
  };
  struct Source {
    Watch watch = Watch::Contact;
    int body = -1;       ///< the apex's, swing's, stop's, fall's or crossing's body
    ContactPair pair{};  ///< a contact's pair
    int axis = -1;       ///< a swing's: 0, 1, 2 for x, y, z
    bool down = false;   ///< a swing's or crossing's value falling through zero, else rising
    Observe observe{};   ///< a crossing's observe
    CrossingFn crossing = nullptr;  ///< a crossing's value
    bool contact() const { return watch == Watch::Contact; }
  };
  /// The event functions the observes' kinds ask for: falls, swings and crossings.
  void watch_observed(const std::vector<Observe>& observed);
  /// The value of event function `s` at `y`: its event is where it falls to zero from above.
  double event_value(const Source& s, const double* y) const;
  /// Whether body i turns on a hinge and may land on the ground (a falling wall).
  bool lands(int i) const;
  /// The angular acceleration (rad/s^2) about its axis of hinged body i at `y`.
  double hinge_alpha(int i, const double* y);
  /// Whether turning hinged body i at `y` the way `alpha` says lowers a corner that touches
  /// the ground: the ground holds it then.
  bool pressed_into_ground(int i, const double* y, double alpha) const;
  /// A hinged body landing on the ground at time t: Newton's restitution about the axis,
  /// omega -> -e omega; a rebound too short to leave, or none, leaves it held there.
  void land(const ContactPair& pair, double* y, double t);
  /// Each body's linear acceleration at `y` into accelerations_: gravity, the force model's
  /// forces (its torques into torque_), and a resting body held on the ground.
  void linear_accelerations(const double* y);
  /// The projection a resting body's acceleration goes through (the identity otherwise).
  Eigen::Matrix3d resting_projection(int body) const;
  /// Adds the force model's derivatives to the Jacobian's velocity rows (after
  /// linear_accelerations() at the same y).
  void add_force_jacobian(const double* y, double* dfdy);
  Eigen::Vector3d momentum(const double* y) const;  ///< N s, of every moving body
  contact::Proximity proximity(const ContactPair& pair, const double* y) const;
  /// Newton's restitution along the contact normal; the ground and fixed bodies do not move.
  void resolve(const ContactPair& pair, double* y, double t);
  /// The hit's contact time and first velocity after it, for each moving body of `pair`.
  void record_hit(const ContactPair& pair, const Eigen::Vector3d& normal, const double* y, double t,
                  bool b_moves);
  /// After a hit: an impulse may lift a resting body off the ground, not press it in.
  void lift_resting(const ContactPair& pair, const double* y, double t);
  /// Ever smaller bounces end: a ground rebound shorter than rest_flight_time() leaves the
  /// body resting on the ground, `gap` (m) from it now.
  void end_small_bounce(const ContactPair& pair, double gap, double* y, double t);
  /// Throws BeyondExactAnswer when another contact on the bodies of `pair` is closed.
  void check_simultaneous(const ContactPair& pair, const double* y, double t) const;
  /// A body resting on a ground with friction at time t: its tangential velocity below
  /// rounding is set to zero, then Coulomb's law decides whether it sticks or slides
  /// (sticking ends its motion: its stop). Free elsewhere.
  void settle(int body, const double* y, double t);
  /// A sliding body's stop event: its velocity along the ground is zeroed, the end of its
  /// motion recorded (it sticks there or turns back), and the body settled anew.
  void stop(int body, double* y, double t);

  const World& scene_;
  BackendSettings settings_;
  std::vector<Source> sources_;
  std::vector<bool> resting_;       ///< per body: resting on the ground
  std::vector<bool> after_bounce_;  ///< per body: an apex is awaited
  EventTrace trace_;
  ForceModel forces_;
  std::vector<Eigen::Vector3d> x_, v_, w_;       ///< the state as arrays, for the force model
  std::vector<Eigen::Quaterniond> q_;            ///< (w_: world spins, q_: normalised)
  std::vector<Eigen::Vector3d> force_, torque_;  ///< N and N m, from the force model
  ForceJacobian force_jacobian_;
  std::vector<Eigen::Vector3d> accelerations_;  ///< m/s^2, from linear_accelerations()
  std::vector<Eigen::Vector3d> applied_;        ///< m/s^2, the same before the ground acts
  std::vector<SlideDecision> slides_;           ///< per body: stuck, sliding or free
  std::vector<double> mu_static_, mu_kinetic_;  ///< per body: its contact with the ground
  std::vector<const Hinge*> hinge_;             ///< per body: the hinge it turns on, or null
  std::vector<bool> held_;        ///< per body: resting, its acceleration projected onto the ground
  std::vector<bool> hinge_held_;  ///< per body: on a hinge, held still by the ground
  /// Per body: in a motion that has not stopped yet (from the start, or from where a push
  /// set it moving from rest); its stop ends the motion, and the trace keeps the last one.
  std::vector<bool> in_motion_;
  /// Body i's motion ends at time t: its stop, unless the motion already stopped (a body
  /// that turned back and slides on is not in a new motion).
  void end_motion(int i, const double* y, double t);
};

}  // namespace bb
