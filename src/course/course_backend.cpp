#include "course/course_backend.hpp"

#include <cmath>

#include "contact/impulse_response.hpp"
#include "course/course_step.hpp"
#include "course/friction_phase.hpp"
#include "course/hinge_turning.hpp"
#include "course/integrators.hpp"
#include "course/rigid_rotation.hpp"
#include "model/contact_pairs.hpp"
#include "model/motion.hpp"
#include "physics/equations_of_motion.hpp"
#include "physics/step_start.hpp"

namespace bb {

namespace {

/// Per body: on a [[hinge]].
std::vector<char> hinged_bodies(const World& scene) {
  std::vector<char> out(scene.bodies.size(), 0);
  for (const Hinge& h : scene.hinges) out[h.body] = 1;
  return out;
}

class CourseSimulation : public Simulation {
 public:
  CourseSimulation(const World& scene, double dt, const CourseVariant& variant)
      : scene_(scene),
        dt_(dt),
        phases_{course::integrator(variant.integrator), course::ground_rule(variant.ground),
                course::friction_rule(variant.friction), course::hit_rule(variant.hit),
                course::spin_rule(variant.spin)},
        contacts_(scene, phases_, dt),
        friction_(scene, phases_.friction, dt),
        hinges_(scene),
        start_(scene, dt),
        equations_(scene) {
    const State start = initial_state(scene);
    take_start(start);
    choose_rotations();
    work_.resize(start.size());
    start_a_.resize(start.size());
    torque_.assign(start.size(), Vec3::Zero());
    settings_ = {{"integrator", variant.integrator}};
    if (!contacts_.empty()) settings_.push_back({"ground_rule", variant.ground});
    record_contact_rules(variant);
    record_friction_rules(variant);
    refuse_hinge_torques();
    record_hinge_rules();
    // A hinged body turns from where the step starts, under the forces there.
    if (!hinges_.empty()) {
      hinge_a_.resize(start.size());
      spins_ = true;
    }
    acceleration_ = [this](const std::vector<Vec3>& x, const std::vector<Vec3>& v,
                           std::vector<Vec3>& a) {
      equations_.accelerations(x, v, omega_, orientation_, a);
      if (!friction_.empty()) friction_.apply(v, a);
    };
  }

  void step() override {
    // Impulses due at the start of this step change velocities (and spins) at once.
    start_.impulses_due([this](const Impulse& imp) { push(imp); });
    // The torques where the step starts turn the bodies over it (L += T dt).
    if (torques_) {
      equations_.accelerations(points_.x, points_.v, omega_, orientation_, start_a_);
      torque_ = equations_.torques();
    }
    // Friction acts on the bodies in contact with the ground as the step starts; the clamp
    // rule stops there a slide that the step would turn back.
    if (!friction_.empty()) {
      friction_.begin(points_.x, orientation_, points_.v);
      if (friction_.stops_slides()) {
        equations_.accelerations(points_.x, points_.v, omega_, orientation_, start_a_);
        friction_.stop_slides(start_a_, points_.v);
      }
    }
    // A hinged body turns from where the step starts, under the forces there.
    if (!hinges_.empty()) {
      equations_.accelerations(points_.x, points_.v, omega_, orientation_, hinge_a_);
      hinge_x_ = points_.x;
      hinge_q_ = orientation_;
    }
    // Forces and integrate: the integrator evaluates the forces at each of its stages.
    phases_.integrate(points_, dt_, acceleration_, work_);
    // Detect, then resolve: the ground rule against fixed surfaces, the blend between bodies.
    if (!contacts_.empty()) {
      contacts_.detect(points_.x, orientation_);
      contacts_.resolve(points_.x, points_.v, orientation_, omega_);
      // A body the ground rule resolved stays in contact for friction (friction_phase.hpp).
      for (const course::FoundContact& c : contacts_.found())
        if (!friction_.empty() && contacts_.pair(c.pair).ground())
          friction_.resolved(contacts_.pair(c.pair).a);
      // A hit may have turned a rigid body: its angular momentum follows its new spin.
      for (const course::FoundContact& c : contacts_.found())
        for (int body : {contacts_.pair(c.pair).a, contacts_.pair(c.pair).b})
          if (body >= 0 && rigid_[body])
            momentum_[body] =
                course::world_inertia(principal_[body], orientation_[body]) * omega_[body];
    }
    // Friction's last word: the clamp rule stops a velocity that crossed zero.
    if (!friction_.empty()) friction_.end(points_.v);
    // Seed section 5. A sphere's spin is kinematic: each frame the orientation is
    // multiplied on the left by the rotation the spin makes in one step (exact for a
    // torque-free sphere). A body whose inertia differs along its axes keeps its angular
    // momentum instead, and its spin follows from it (rigid_rotation.hpp), as does a body
    // a torque turns.
    if (spins_)
      for (std::size_t i = 0; i < omega_.size(); ++i) {
        if (rigid_[i]) {
          course::rotate_rigid(principal_[i], torque_[i], dt_, momentum_[i], orientation_[i],
                               omega_[i]);
          continue;
        }
        orientation_[i] =
            (quat_from_rotation_vector(omega_[i], dt_) * orientation_[i]).normalized();
      }
    // Seed section 5, the plank on an axis: a hinged body's step replaces the free one.
    if (!hinges_.empty()) {
      points_.x.swap(hinge_x_);
      orientation_.swap(hinge_q_);
      for (std::size_t i = 0; i < hinge_x_.size(); ++i)
        if (!hinged_[i]) points_.x[i] = hinge_x_[i], orientation_[i] = hinge_q_[i];
      hinges_.step(dt_, hinge_a_, points_.x, points_.v, orientation_, omega_);
    }
  }

  void read(State& out) const override {
    for (std::size_t i = 0; i < out.size(); ++i)
      out[i] = {points_.x[i], points_.v[i], orientation_[i], omega_[i]};
  }

  Settings settings() const override { return settings_; }

 private:
  /// Each body's position, velocity, orientation and spin where the run starts.
  void take_start(const State& start) {
    for (const BodyState& b : start) {
      points_.x.push_back(b.position);
      points_.v.push_back(b.velocity);
      orientation_.push_back(b.orientation);
      omega_.push_back(b.angular_velocity);
      spins_ = spins_ || b.angular_velocity.norm() > 0.0;
    }
  }

  /// A body whose inertia differs along its axes, or that a torque turns, turns by the
  /// seed's rotation with physics (L += T dt).
  void choose_rotations() {
    torques_ = equations_.forces().torques();
    for (std::size_t i = 0; i < scene_.bodies.size(); ++i) {
      const Body& b = scene_.bodies[i];
      const Vec3 principal = principal_inertia(b);
      principal_.push_back(principal);
      const bool turned = torques_ && !b.torque.isZero() && principal.minCoeff() > 0.0;
      rigid_.push_back(!b.fixed && (principal.maxCoeff() > principal.minCoeff() || turned));
      spins_ = spins_ || (!b.fixed && turned);
      momentum_.push_back(course::world_inertia(principal, orientation_[i]) * omega_[i]);
    }
  }

  /// The friction rule and what it does, where the scene has friction.
  void record_friction_rules(const CourseVariant& variant) {
    if (friction_.empty()) return;
    settings_.push_back({"friction_rule", variant.friction});
    settings_.push_back(
        {"friction_contact",
         std::string("a body in contact with the ground at the step's start feels friction "
                     "throughout the step, whatever the ground rule: within 1e-9 m of it or "
                     "overlapping it, or in contact or resolved against it in the step "
                     "before and back on it within four steps under gravity alone (gap + "
                     "v_n T - g_n T^2 / 2 <= 1e-9 m, T = 4 dt); N from the other forces "
                     "pressing it on the ground; a "
                     "tangential speed under 1e-12 m/s counts as rest")});
    if (variant.friction == "clamp")
      settings_.push_back(
          {"friction_stop",
           std::string("clamp: before each step, a slide that the step's kinetic friction "
                       "(less the other forces' pull along it) would turn back stops: its "
                       "velocity along the ground becomes 0 and static friction takes the "
                       "step; after the step, a velocity along the ground that turned back "
                       "anyway is set to 0")});
  }

  /// The course's hinge turns a body by the forces at its centre only: a torque of the body's
  /// own is a scene it cannot run.
  void refuse_hinge_torques() const {
    for (const Hinge& h : scene_.hinges)
      if (!scene_.bodies[h.body].torque.isZero())
        throw UnsupportedScene("the course's hinge (seed section 5) turns body '" +
                               scene_.bodies[h.body].name +
                               "' by the torque of the forces at its centre; a torque of its "
                               "own is not modelled there");
  }

  /// The hinge's rule, and the clamp against the ground of a hinged box, where the scene
  /// has hinges.
  void record_hinge_rules() {
    if (hinges_.empty()) return;
    settings_.push_back(
        {"hinge", std::string("seed section 5, the plank on an axis: L += T dt (T the torque "
                              "of the forces at the centre about the axis), omega = L / J "
                              "with the seed's J = 1/3 m d1^2 + 1/3 m d2^2 (a box as a plank "
                              "along its longest side, split at the axis), the centre carried "
                              "round the anchor")});
    for (const Hinge& h : scene_.hinges)
      if (ground_pair(scene_, h.body) && scene_.bodies[h.body].shape == Shape::Box) {
        settings_.push_back(
            {"hinge_ground", std::string("a step that would turn a hinged box further below "
                                         "the ground is not taken and its L becomes -e L "
                                         "(section 3's clamp rule applied to the angle)")});
        break;
      }
  }

  /// The hit and spin rules, where the scene has a ball that can meet a moving box, or a
  /// ball that touches anything.
  void record_contact_rules(const CourseVariant& variant) {
    bool hits = false, balls = false;
    for (const ContactPair& p : contact_pairs(scene_)) {
      const bool ball = scene_.bodies[p.a].shape == Shape::Sphere;
      balls = balls || ball;
      hits = hits || (ball && !p.ground() && !scene_.bodies[p.b].fixed &&
                      scene_.bodies[p.b].shape == Shape::Box);
    }
    if (hits) settings_.push_back({"hit_rule", variant.hit});
    if (balls) settings_.push_back({"spin_rule", variant.spin});
    spins_ = spins_ || hits || variant.spin != "free";
  }

  void push(const Impulse& imp) {
    const std::size_t i = static_cast<std::size_t>(imp.body);
    if (hinges_.push(imp, points_.x, points_.v, omega_)) return;
    contact::apply_impulse(scene_.bodies[i], imp, points_.x[i], orientation_[i], points_.v[i],
                           omega_[i]);
    momentum_[i] = course::world_inertia(principal_[i], orientation_[i]) * omega_[i];
    spins_ = spins_ || omega_[i].norm() > 0.0;
  }

  const World& scene_;
  double dt_;
  course::Phases phases_;
  course::ContactPhases contacts_;
  course::FrictionPhase friction_;
  course::HingeTurning hinges_;
  std::vector<char> hinged_ = hinged_bodies(scene_);
  std::vector<Vec3> hinge_a_, hinge_x_;  ///< accelerations and positions at the step's start
  std::vector<Vec3> start_a_;            ///< accelerations at the step's start, for the clamp stop
  std::vector<Quat> hinge_q_;            ///< orientations at the step's start
  StepStart start_;                      ///< impulses due
  EquationsOfMotion equations_;
  course::PointState points_;
  course::Workspace work_;
  course::AccelerationFn acceleration_;
  std::vector<Quat> orientation_;
  std::vector<Vec3> omega_;
  std::vector<Vec3> principal_;  ///< principal moments of inertia, kg m^2
  std::vector<char> rigid_;      ///< per body: turned by rigid rotation, not kinematically
  std::vector<Vec3> momentum_;   ///< angular momentum, world frame (rigid bodies)
  std::vector<Vec3> torque_;     ///< N m, world frame, at the step's start
  bool torques_ = false;         ///< some term gives a torque
  bool spins_ = false;
  Settings settings_;
};

}  // namespace

FeatureSet CourseBackend::supports() const {
  return force_stage_features() | FeatureSet{Feature::ThreeD,        Feature::Rotation,
                                             Feature::GroundContact, Feature::BodyContact,
                                             Feature::Restitution,   Feature::Impulse,
                                             Feature::Springs,       Feature::Friction,
                                             Feature::Boxes,         Feature::Hinge};
}

std::unique_ptr<Simulation> CourseBackend::start_run(const World& scene, const BackendSettings&,
                                                     double dt) const {
  return std::make_unique<CourseSimulation>(scene, dt, variant_);
}

}  // namespace bb
