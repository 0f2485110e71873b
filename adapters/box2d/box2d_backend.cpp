// Box2D 2.4 as a plugin of two backends: 2D scenes only, single precision. `box2d`, whose
// springs are distance joints with stiffness and damping, and `box2d/force`, whose springs
// are forces added before each step.
#include <box2d/box2d.h>

#include <cfloat>
#include <cmath>
#include <memory>
#include <vector>

#include "../described_backend.hpp"
#include "../engine_caps.hpp"
#include "../point_body.hpp"
#include "box2d_contacts.hpp"
#include "box2d_engine.hpp"
#include "box2d_hinges.hpp"
#include "box2d_vectors.hpp"
#include "physics/step_start.hpp"
#include "seam/engine_catalogue.hpp"
#include "seam/engine_keys.hpp"
#include "seam/plugin_api.hpp"

namespace bb {

namespace {

/// Box2D 2.4.1's caps on a step's motion (b2_common.h), applied in b2Island::Solve.
constexpr StepCap kMaxTranslation{
    "Box2D",
    "held body",
    "at its cap of",
    b2_maxTranslation,
    "2 m",
    "m/s",
    "b2_maxTranslation, built in: b2Island::Solve scales a faster velocity down so that the "
    "body moves 2 m in the step"};
constexpr StepCap kMaxRotation{
    "Box2D",
    "held body",
    "at its cap of",
    b2_maxRotation,
    "pi/2 rad",
    "rad/s",
    "b2_maxRotation, built in: b2Island::Solve scales a faster spin down so that the body "
    "turns pi/2 rad in the step"};

class Box2dSimulation : public Simulation {
 public:
  Box2dSimulation(const World& scene, const EngineTables& engines, double dt, SpringsAs springs)
      : scene_(scene),
        engines_(engines),
        springs_(springs),
        start_(scene, dt, {springs == SpringsAs::Forces}),
        dt_(float(dt)),
        world_(to_b2(scene.gravity)) {
    velocity_iterations_ =
        static_cast<int>(engine_setting(engines, box2d_description(), "velocity_iterations"));
    position_iterations_ =
        static_cast<int>(engine_setting(engines, box2d_description(), "position_iterations"));
    world_.SetAllowSleeping(false);
    const bool contacts = has_contacts(scene);
    for (const Body& b : scene.bodies) {
      b2BodyDef def;
      def.type = b.fixed ? b2_staticBody : b2_dynamicBody;
      def.position = to_b2(b.position);
      def.angle = float(angle_about_z(b.orientation));
      def.linearVelocity = to_b2(b.velocity);
      def.angularVelocity = float(b.angular_velocity.z());
      def.linearDamping = float(engine_setting(engines, box2d_description(), "linear_damping"));
      def.angularDamping = float(engine_setting(engines, box2d_description(), "angular_damping"));
      def.allowSleep = false;
      def.bullet =
          contacts && !b.fixed && engine_setting(engines, box2d_description(), "bullet") != 0.0;
      b2Body* body = world_.CreateBody(&def);
      bodies_.push_back(body);
    }
    // Fixtures only where something can touch; they carry no mass of their own.
    if (contacts)
      contacts_ = std::make_unique<Box2dContacts>(
          scene, world_, bodies_,
          float(engine_setting(engines, box2d_description(), "restitution_threshold")));
    // Mass and inertia set directly: Box2D's circle would be a disc. A point body gets a
    // small sphere's inertia, as in every engine (point_body.hpp).
    for (std::size_t i = 0; i < bodies_.size(); ++i)
      if (!scene.bodies[i].fixed) {
        const Body& b = scene.bodies[i];
        b2MassData mass{float(b.mass), b2Vec2(0.0f, 0.0f), float(engine_inertia(b).z())};
        bodies_[i]->SetMassData(&mass);
      }
    if (springs_ == SpringsAs::Joints) make_spring_joints();
    make_box2d_hinges(scene, world_, bodies_);
  }

  void step() override {
    // Impulses due at the start of this step, through the engine's own API; then the force
    // model's loads from the engine's own current state, as a game would add them.
    start_.impulses_due([this](const Impulse& imp) { push(imp); });
    if (start_.has_loads()) {
      read(state_);
      const Loads& loads = start_.loads(state_);
      for (std::size_t i = 0; i < bodies_.size(); ++i) {
        if (scene_.bodies[i].fixed) continue;
        bodies_[i]->ApplyForceToCenter(to_b2(loads.force[i]), true);
        if (start_.torques()) bodies_[i]->ApplyTorque(float(loads.torque[i].z()), true);
      }
    }
    world_.Step(dt_, velocity_iterations_, position_iterations_);
    ++steps_;
    // A body Box2D held at a cap leaves the step at it; the first one is reported.
    if (!caps_.held())
      for (std::size_t i = 0; i < bodies_.size(); ++i) {
        if (scene_.bodies[i].fixed) continue;
        caps_.check(kMaxTranslation, i, bodies_[i]->GetLinearVelocity().Length(), steps_);
        caps_.check(kMaxRotation, i, std::abs(bodies_[i]->GetAngularVelocity()), steps_);
      }
  }

  std::vector<EngineIntervention> interventions() const override { return caps_.interventions(); }

  void read(State& out) const override {
    for (std::size_t i = 0; i < bodies_.size(); ++i) {
      const b2Body& body = *bodies_[i];
      const b2Vec2 p = body.GetPosition();
      const b2Vec2 v = body.GetLinearVelocity();
      out[i] = {Vec3(p.x, p.y, 0.0), Vec3(v.x, v.y, 0.0),
                quat_from_axis_angle(Vec3::UnitZ(), body.GetAngle()),
                Vec3(0.0, 0.0, body.GetAngularVelocity())};
    }
  }

  Settings settings() const override {
    Settings s = engine_key_settings(engines_, box2d_description());
    s.push_back({"precision", std::string("float")});
    s.push_back({"sleeping", false});
    if (contacts_)
      add_contact_settings(scene_, *contacts_, s);
    else
      s.push_back({"collision", std::string("none (no fixtures; mass set with SetMassData)")});
    if (!scene_.springs.empty() && springs_ == SpringsAs::Forces)
      s.push_back({"springs", std::string("force k (l - L) + c (v_b - v_a).u along each spring, "
                                          "added with b2Body::ApplyForceToCenter before each "
                                          "step")});
    if (!scene_.springs.empty() && springs_ == SpringsAs::Joints) {
      s.push_back(
          {"springs", std::string("a distance joint (b2DistanceJointDef) per spring between the "
                                  "bodies' centres: length = the rest length, stiffness = k N/m, "
                                  "damping = c N s/m, minLength 0 and maxLength FLT_MAX so no "
                                  "limit acts; Box2D solves it as a soft constraint (implicit in "
                                  "the spring), in float")});
      s.push_back({"spring_stiffness_first", double(first_stiffness_)});
    }
    if (!scene_.springs.empty()) s.push_back({"spring_bodies_collide", false});
    if (!scene_.hinges.empty()) add_box2d_hinge_settings(s);
    if (!scene_.impulses.empty())
      s.push_back({"impulse", std::string("b2Body::ApplyLinearImpulse(J, point, true) before "
                                          "the step that starts at the impulse's time: J's x "
                                          "and y; the spin follows from the point")});
    add_point_body_setting(scene_, s);
    s.push_back({"max_translation", std::string("2 m per step (b2_maxTranslation, built in); a "
                                                "body held at it is reported as a cap")});
    s.push_back({"max_rotation", std::string("pi/2 rad per step (b2_maxRotation, built in); a "
                                             "body held at it is reported as a cap")});
    if (scene_.features().has(Feature::Rotation))
      s.push_back({"gyroscopic", std::string("none: a 2D body turns about z only, where w x I w "
                                             "is zero")});
    return s;
  }

 private:
  static bool has_contacts(const World& scene) {
    return scene.ground.has_value() || !scene.contacts.empty();
  }

  /// Each spring as Box2D's distance joint with its own stiffness and damping (Box2D 2.4
  /// takes them in N/m and N s/m), free of its length limits.
  void make_spring_joints() {
    for (const Spring& spring : scene_.springs) {
      b2DistanceJointDef def;
      def.bodyA = bodies_[static_cast<std::size_t>(spring.body_a)];
      def.bodyB = bodies_[static_cast<std::size_t>(spring.body_b)];
      def.localAnchorA.SetZero();
      def.localAnchorB.SetZero();
      def.length = float(spring.rest_length);
      def.minLength = 0.0f;
      def.maxLength = FLT_MAX;
      def.stiffness = float(spring.stiffness);
      def.damping = float(spring.damping);
      def.collideConnected = false;
      world_.CreateJoint(&def);
      if (first_stiffness_ == 0.0f) first_stiffness_ = def.stiffness;
    }
  }

  void push(const Impulse& imp) {
    b2Body* body = bodies_[static_cast<std::size_t>(imp.body)];
    const b2Vec2 point = imp.point ? to_b2(*imp.point) : body->GetWorldCenter();
    body->ApplyLinearImpulse(to_b2(imp.impulse), point, true);
  }

  const World& scene_;
  const EngineTables& engines_;  ///< the case's [engines.box2d] table among the others
  SpringsAs springs_;            ///< box2d: Box2D's joints; box2d/force: forces
  StepStart start_;              ///< impulses due and the force model's loads
  float dt_;
  int velocity_iterations_ = 8;
  int position_iterations_ = 3;
  /// Null when nothing can touch; declared before the world, which points at it, so that
  /// it outlives the world.
  std::unique_ptr<Box2dContacts> contacts_;
  b2World world_;
  std::vector<b2Body*> bodies_;
  State state_{scene_.bodies.size()};  ///< read before each step for the forces
  float first_stiffness_ = 0.0f;       ///< the first joint's stiffness as Box2D holds it
  long steps_ = 0;                     ///< steps taken
  CapWatch caps_{scene_, double(dt_), double(FLT_EPSILON)};  ///< the first body held at a cap
};

/// Library and version: the installed package's; the library's b2_version lags behind in 2.4.1.
std::pair<std::string, std::string> box2d_version() {
  const std::string header = std::to_string(b2_version.major) + "." +
                             std::to_string(b2_version.minor) + "." +
                             std::to_string(b2_version.revision);
  const std::string package = BOX2D_PACKAGE_VERSION;
  if (package == header) return {"box2d", package};
  return {"box2d", package + " (its b2_version says " + header + ")"};
}

}  // namespace

}  // namespace bb

namespace {

/// The plugin's backends: the springs as Box2D's joints, or as forces.
bb::Backend* box2d_backend(int index) {
  using bb::SpringsAs;
  static const std::vector<bb::VariantStart> starts = {
      {"box2d", bb::start_engine<bb::Box2dSimulation>(SpringsAs::Joints)},
      {"box2d/force", bb::start_engine<bb::Box2dSimulation>(SpringsAs::Forces)}};
  return bb::engine_backend(bb::box2d_description(), bb::box2d_version(), starts, index);
}

}  // namespace

BEACHBALL_PLUGIN_BACKENDS(box2d_backend)
