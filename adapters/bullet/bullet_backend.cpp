// Bullet's rigid bodies as a backend, built against Bullet's double-precision libraries
// (backends "bullet", and "bullet/force" whose springs are forces applied before each step
// instead of Bullet's own constraints: bullet_plugin.cpp) and its single-precision ones
// ("bullet-float": bullet_float_plugin.cpp).
#include <btBulletDynamicsCommon.h>

#include <cfloat>
#include <cmath>
#include <memory>
#include <optional>
#include <vector>

#include "../described_backend.hpp"
#include "../engine_caps.hpp"
#include "../engine_friction.hpp"
#include "../point_body.hpp"
#include "bullet_contacts.hpp"
#include "bullet_engine.hpp"
#include "bullet_gyroscopic.hpp"
#include "bullet_hinges.hpp"
#include "bullet_pools.hpp"
#include "bullet_settings.hpp"
#include "bullet_springs.hpp"
#include "bullet_vectors.hpp"
#include "physics/step_start.hpp"
#include "seam/engine_catalogue.hpp"
#include "seam/engine_keys.hpp"
#include "seam/plugin_api.hpp"

namespace bb {

namespace {

/// How bullet/force applies the springs, for engine_settings.
constexpr const char* kSpringsByHandMethod =
    "applied by hand: before each step k (l - L) + c (v_b - v_a).u from the engine's own "
    "state (external_forces), btRigidBody::applyCentralForce; no constraint, so no stiffness "
    "limit; anchored particles static (mass 0)";

/// What a 2D scene's moving bodies are held by, for engine_settings.
constexpr const char* kPlane2d =
    "btRigidBody::setLinearFactor(1, 1, 0) and setAngularFactor(0, 0, 1) on every moving "
    "body: the solver, forces and integration leave z and the spin about x and y untouched, "
    "so each body stays at its z (0) and turns about z only";

/// Bullet 3.24's cap on a step's turn: btDiscreteDynamicsWorld integrates each orientation
/// with btTransformUtil::integrateTransform, which past ANGULAR_MOTION_THRESHOLD takes the
/// angle as the threshold's but the axis part from the whole spin, so the orientation turns
/// by 2 atan((w dt / (pi/4)) tan(pi/8)), less than w dt, and the angular velocity stays what it
/// was (btRigidBody::integrateVelocities's MAX_ANGVEL belongs to btSimpleDynamicsWorld and is
/// never called here).
constexpr StepCap kAngularMotionThreshold{
    "Bullet",
    "slowed the turn of body",
    "past its cap of",
    double(ANGULAR_MOTION_THRESHOLD),
    "pi/4 rad",
    "rad/s",
    "ANGULAR_MOTION_THRESHOLD, built into btTransformUtil::integrateTransform: past it a step "
    "turns the orientation by 2 atan((w dt / (pi/4)) tan(pi/8)), less than w dt, and keeps the "
    "angular velocity, so the orientation lags the spin"};

/// The radius of the largest sphere inside a body: what CCD sweeps and its motion threshold.
double inner_radius(const Body& b) {
  return b.shape == Shape::Box ? b.half_extents.minCoeff() : b.radius;
}

class BulletSimulation : public Simulation {
 public:
  BulletSimulation(const World& scene, const EngineTables& engines, double dt, SpringsAs springs)
      : scene_(scene),
        engines_(engines),
        springs_(springs),
        dt_(dt),
        contacts_(scene_has_contacts(scene)) {
    world_.setGravity(to_bt(scene.gravity));
    dispatcher_.setDispatcherFlags(
        btCollisionDispatcher::CD_USE_RELATIVE_CONTACT_BREAKING_THRESHOLD);
    configure_solver(engines, world_.getSolverInfo());
    // Set whatever its value (bullet_contacts.hpp). The dispatcher, built already, holds
    // the configuration's create functions, which this call changes in place.
    configuration_.setPlaneConvexMultipointIterations(multipoint_.iterations,
                                                      multipoint_.threshold);
    if (contacts_) {
      pairs_ = std::make_unique<PairTable>(scene);
      filter_ = std::make_unique<PairFilter>(*pairs_);
      world_.getPairCache()->setOverlapFilterCallback(filter_.get());
      install_pair_material_callback();
    }
    for (std::size_t i = 0; i < scene.bodies.size(); ++i)
      add_body(scene.bodies[i], static_cast<int>(i));
    if (scene.ground) add_ground(*scene.ground);
    if (springs_ == SpringsAs::Joints && !scene.springs.empty())
      joints_ = std::make_unique<BulletSpringJoints>(scene, engines, dt, bodies_, world_);
    if (!scene.hinges.empty())
      hinges_ = std::make_unique<BulletHingeJoints>(scene, bodies_, world_);
  }
  ~BulletSimulation() override {
    joints_.reset();
    hinges_.reset();
    for (auto& body : bodies_) world_.removeRigidBody(body.get());
    if (ground_) world_.removeRigidBody(ground_.get());
  }

  void step() override {
    // Impulses due at the start of this step, through the engine's own API; then the force
    // model's loads from the engine's own current state, as a game would add them (in
    // bullet/force the springs too).
    start_.impulses_due([this](const Impulse& imp) { push(imp); });
    if (start_.has_loads()) {
      read(state_);
      const Loads& loads = start_.loads(state_);
      for (std::size_t i = 0; i < bodies_.size(); ++i) {
        if (scene_.bodies[i].fixed) continue;
        bodies_[i]->applyCentralForce(to_bt(loads.force[i]));
        if (start_.torques()) bodies_[i]->applyTorque(to_bt(loads.torque[i]));
      }
    }
    // Bullet's springs pull along their frames: aimed along the bodies' line at each step.
    if (joints_) joints_->aim();
    // One fixed substep of exactly dt: no interpolation, no accumulator.
    world_.stepSimulation(btScalar(dt_), 1, btScalar(dt_));
    ++steps_;
    // A body spinning past the cap turns by less than its spin; the first one is reported.
    if (!caps_.held())
      for (std::size_t i = 0; i < bodies_.size(); ++i)
        if (!scene_.bodies[i].fixed)
          caps_.check(kAngularMotionThreshold, i, double(bodies_[i]->getAngularVelocity().length()),
                      steps_);
  }

  std::vector<EngineIntervention> interventions() const override { return caps_.interventions(); }

  void read(State& out) const override {
    for (std::size_t i = 0; i < bodies_.size(); ++i) {
      const btRigidBody& body = *bodies_[i];
      const btTransform& t = body.getWorldTransform();
      const btQuaternion q = t.getRotation();
      out[i] = {from_bt(t.getOrigin()),
                from_bt(body.getLinearVelocity()),
                {q.w(), q.x(), q.y(), q.z()},
                from_bt(body.getAngularVelocity())};
    }
  }

  Settings settings() const override {
    Settings s = engine_key_settings(engines_, bullet_description());
    s.push_back(
        {"precision", sizeof(btScalar) == 8 ? std::string("double") : std::string("float")});
    s.push_back({"step", std::string("stepSimulation(dt, 1, dt): one fixed substep")});
    s.push_back({"sleeping", false});
    s.push_back({"deactivation",
                 std::string("setActivationState(DISABLE_DEACTIVATION) on every body; with "
                             "Bullet's default a body slower than 0.8 m/s and 1 rad/s for 2 s "
                             "(gDeactivationTime) would freeze, a slow oscillator with it")});
    if (joints_) joints_->add_settings(s);
    if (hinges_) hinges_->add_settings(s);
    if (springs_ == SpringsAs::Forces && !scene_.springs.empty())
      s.push_back({"springs", std::string(kSpringsByHandMethod)});
    if (contacts_)
      add_contact_settings(scene_, engines_, world_.getSolverInfo(), shape_figures_, multipoint_,
                           s);
    else
      s.push_back({"collision", std::string("none (btEmptyShape, collision mask 0)")});
    if (!scene_.impulses.empty()) s.push_back({"impulse", std::string(kImpulseMethod)});
    add_point_body_setting(scene_, s);
    s.push_back({"max_turn", std::string("pi/4 rad per step (ANGULAR_MOTION_THRESHOLD, built into "
                                         "btTransformUtil::integrateTransform): a faster spin "
                                         "keeps its angular velocity and turns the orientation "
                                         "by 2 atan((w dt / (pi/4)) tan(pi/8)) a step, less than "
                                         "w dt; a body past it is reported as a cap")});
    add_bullet_gyroscopic_setting(engines_, s);
    s.push_back({"plane_2d", std::string(scene_.dims == 2 ? kPlane2d : "none (3D scene)")});
    return s;
  }

 private:
  void add_body(const Body& b, int index) {
    std::unique_ptr<btCollisionShape> shape = contacts_ ? make_shape(b) : nullptr;
    // Without a shape (no contacts, or a point) a body gets an empty one and collides with
    // nothing. A point body gets a small sphere's inertia, as in every engine (point_body.hpp).
    const btScalar mass = b.fixed ? btScalar(0) : btScalar(b.mass);
    btRigidBody::btRigidBodyConstructionInfo info(
        mass, nullptr, shape ? shape.get() : &empty_shape_, to_bt(engine_inertia(b)));
    info.m_startWorldTransform.setOrigin(to_bt(b.position));
    info.m_startWorldTransform.setRotation(
        btQuaternion(btScalar(b.orientation.x()), btScalar(b.orientation.y()),
                     btScalar(b.orientation.z()), btScalar(b.orientation.w())));
    info.m_linearDamping =
        btScalar(engine_setting(engines_, bullet_description(), "linear_damping"));
    info.m_angularDamping =
        btScalar(engine_setting(engines_, bullet_description(), "angular_damping"));
    auto body = std::make_unique<btRigidBody>(info);
    if (!b.fixed) {
      body->setLinearVelocity(to_bt(b.velocity));
      body->setAngularVelocity(to_bt(b.angular_velocity));
      set_bullet_gyroscopic(engines_, *body);
      // A 2D scene stays in the x-y plane, as a 2D game sets Bullet up.
      if (scene_.dims == 2) {
        body->setLinearFactor(btVector3(1, 1, 0));
        body->setAngularFactor(btVector3(0, 0, 1));
      }
    }
    body->setActivationState(DISABLE_DEACTIVATION);
    body->setUserIndex(index);
    if (shape) {
      take_part_in_contacts(*body);
      // Bullet's own rule multiplies restitutions and frictions; with the ground's set to 1
      // it already gives the body's ground pair the case's value. The callback sets every
      // pair (engine_friction.hpp: the one coefficient is friction_kinetic).
      if (const std::optional<ContactPair> ground = ground_pair(scene_, index)) {
        body->setRestitution(btScalar(ground->restitution));
        body->setFriction(btScalar(engine_friction(*ground)));
      }
      if (engine_setting(engines_, bullet_description(), "ccd") != 0.0 && !b.fixed) {
        body->setCcdMotionThreshold(btScalar(inner_radius(b)));
        body->setCcdSweptSphereRadius(btScalar(inner_radius(b)));
      }
      // Bullet's defaults, set or read back explicitly: every contact point goes to the
      // solver; a pair's points start within the smaller of its shapes' thresholds.
      body->setContactProcessingThreshold(BT_LARGE_FLOAT);
      shape_figures_.margins.push_back(double(shape->getMargin()));
      shape_figures_.breaking_thresholds.push_back(
          double(shape->getContactBreakingThreshold(gContactBreakingThreshold)));
      shapes_.push_back(std::move(shape));
      world_.addRigidBody(body.get());
    } else {
      world_.addRigidBody(body.get(), 1, 0);
    }
    bodies_.push_back(std::move(body));
  }

  void add_ground(const Ground& ground) {
    ground_shape_ = make_ground_shape(ground);
    btRigidBody::btRigidBodyConstructionInfo info(0, nullptr, ground_shape_.get());
    ground_ = std::make_unique<btRigidBody>(info);
    ground_->setUserIndex(pairs_->ground_index());
    ground_->setRestitution(1);
    ground_->setFriction(1);
    ground_->setContactProcessingThreshold(BT_LARGE_FLOAT);
    take_part_in_contacts(*ground_);
    world_.addRigidBody(ground_.get());
  }

  /// Marks an object for the pair-material callback and points it at this run's pairs.
  void take_part_in_contacts(btRigidBody& body) {
    body.setCollisionFlags(body.getCollisionFlags() |
                           btCollisionObject::CF_CUSTOM_MATERIAL_CALLBACK);
    body.setUserPointer(pairs_.get());
  }

  void push(const Impulse& imp) {
    btRigidBody& body = *bodies_[static_cast<std::size_t>(imp.body)];
    const btVector3 centre = body.getCenterOfMassPosition();
    const btVector3 arm = imp.point ? to_bt(*imp.point) - centre : btVector3(0, 0, 0);
    body.activate(true);
    body.applyImpulse(to_bt(imp.impulse), arm);
  }

  const World& scene_;
  const EngineTables& engines_;  ///< the case's [engines.bullet] table among the others
  SpringsAs springs_;  ///< bullet, bullet-float: Bullet's constraints; bullet/force: forces
  double dt_;
  bool contacts_;
  PlaneMultipoint multipoint_ = plane_multipoint(scene_);
  btDefaultCollisionConfiguration configuration_{pools_for(scene_)};
  btCollisionDispatcher dispatcher_{&configuration_};
  btDbvtBroadphase broadphase_;
  btSequentialImpulseConstraintSolver solver_;
  btDiscreteDynamicsWorld world_{&dispatcher_, &broadphase_, &solver_, &configuration_};
  btEmptyShape empty_shape_;
  std::unique_ptr<PairTable> pairs_;
  std::unique_ptr<PairFilter> filter_;
  std::vector<std::unique_ptr<btCollisionShape>> shapes_;
  ShapeFigures shape_figures_;
  std::unique_ptr<btCollisionShape> ground_shape_;
  std::unique_ptr<btRigidBody> ground_;
  std::vector<std::unique_ptr<btRigidBody>> bodies_;
  std::unique_ptr<BulletSpringJoints> joints_;  ///< the springs as constraints, or none
  std::unique_ptr<BulletHingeJoints> hinges_;   ///< the hinges as constraints, or none
  StepStart start_{scene_, dt_, {springs_ == SpringsAs::Forces}};  ///< impulses due, the loads
  State state_{scene_.bodies.size()};  ///< read before each step for the forces
  long steps_ = 0;                     ///< steps taken
  /// The first body held at the cap, judged to the rounding of btScalar.
  CapWatch caps_{scene_, dt_, sizeof(btScalar) == 8 ? DBL_EPSILON : double(FLT_EPSILON)};
};

}  // namespace

DeclaredBackend::Start bullet_rigid_start(SpringsAs springs) {
  return start_engine<BulletSimulation>(springs);
}

}  // namespace bb
