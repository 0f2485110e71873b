// Bullet as a backend. Built twice from this file: against Bullet's double-precision
// libraries (backend "bullet") and its single-precision ones ("bullet-float").
#include <btBulletDynamicsCommon.h>

#include <memory>
#include <vector>

#include "../point_body.hpp"
#include "scene/engine_keys.hpp"
#include "scene/external_forces.hpp"
#include "scene/plugin_api.hpp"

namespace bb {

namespace {

btVector3 to_bt(const Vec3& v) {
  return {btScalar(v.x()), btScalar(v.y()), btScalar(v.z())};
}
Vec3 from_bt(const btVector3& v) {
  return {v.x(), v.y(), v.z()};
}

class BulletSimulation : public Simulation {
 public:
  BulletSimulation(const Scene& scene, double dt) : scene_(scene), dt_(btScalar(dt)) {
    world_.setGravity(to_bt(scene.gravity));
    btContactSolverInfo& solver = world_.getSolverInfo();
    solver.m_numIterations = static_cast<int>(engine_setting(scene, "bullet", "solver_iterations"));
    solver.m_erp = btScalar(engine_setting(scene, "bullet", "erp"));
    solver.m_splitImpulse = engine_setting(scene, "bullet", "split_impulse") != 0.0;
    const btScalar linear_damping = btScalar(engine_setting(scene, "bullet", "linear_damping"));
    const btScalar angular_damping = btScalar(engine_setting(scene, "bullet", "angular_damping"));
    for (const Body& b : scene.bodies) {
      // No contacts in the scene: every body gets an empty shape and collides with nothing.
      // A point body gets a small sphere's inertia, as in every engine (point_body.hpp).
      const btScalar mass = b.fixed ? btScalar(0) : btScalar(b.mass);
      btRigidBody::btRigidBodyConstructionInfo info(mass, nullptr, &empty_shape_,
                                                    to_bt(engine_inertia(b)));
      info.m_startWorldTransform.setOrigin(to_bt(b.position));
      info.m_startWorldTransform.setRotation(
          btQuaternion(btScalar(b.orientation.x()), btScalar(b.orientation.y()),
                       btScalar(b.orientation.z()), btScalar(b.orientation.w())));
      info.m_linearDamping = linear_damping;
      info.m_angularDamping = angular_damping;
      auto body = std::make_unique<btRigidBody>(info);
      if (!b.fixed) {
        body->setLinearVelocity(to_bt(b.velocity));
        body->setAngularVelocity(to_bt(b.angular_velocity));
      }
      body->setActivationState(DISABLE_DEACTIVATION);
      world_.addRigidBody(body.get(), 1, 0);
      bodies_.push_back(std::move(body));
    }
  }
  ~BulletSimulation() override {
    for (auto& body : bodies_) world_.removeRigidBody(body.get());
  }

  void step() override {
    // The harness's forces from the engine's own current state, as a game would add them.
    if (has_external_forces(scene_)) {
      read(state_);
      external_forces(scene_, state_, forces_);
      for (std::size_t i = 0; i < bodies_.size(); ++i)
        if (!scene_.bodies[i].fixed) bodies_[i]->applyCentralForce(to_bt(forces_[i]));
    }
    // One fixed substep of exactly dt: no interpolation, no accumulator.
    world_.stepSimulation(dt_, 1, dt_);
  }

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
    Settings s = engine_key_settings(scene_, "bullet");
    s.push_back(
        {"precision", sizeof(btScalar) == 8 ? std::string("double") : std::string("float")});
    s.push_back({"step", std::string("stepSimulation(dt, 1, dt): one fixed substep")});
    s.push_back({"sleeping", false});
    s.push_back({"collision", std::string("none (btEmptyShape, collision mask 0)")});
    add_point_body_setting(scene_, s);
    s.push_back({"max_angular_speed", std::string("pi/2 rad per step (built into btRigidBody)")});
    return s;
  }

 private:
  const Scene& scene_;
  btScalar dt_;
  btDefaultCollisionConfiguration configuration_;
  btCollisionDispatcher dispatcher_{&configuration_};
  btDbvtBroadphase broadphase_;
  btSequentialImpulseConstraintSolver solver_;
  btDiscreteDynamicsWorld world_{&dispatcher_, &broadphase_, &solver_, &configuration_};
  btEmptyShape empty_shape_;
  std::vector<std::unique_ptr<btRigidBody>> bodies_;
  State state_{scene_.bodies.size()};  ///< read before each step for the forces
  std::vector<Vec3> forces_;
};

class BulletBackend : public Backend {
 public:
  std::string name() const override { return BB_BULLET_NAME; }
  FeatureSet supports() const override {
    return {Feature::ThreeD, Feature::Gravity,  Feature::Drag, Feature::Magnus,
            Feature::Wind,   Feature::Rotation, Feature::Boxes};
  }
  std::pair<std::string, std::string> library_version() const override {
    const int v = btGetVersion();
    return {"bullet", std::to_string(v / 100) + "." + std::to_string(v % 100)};
  }
  std::unique_ptr<Simulation> start(const Scene& scene, double dt) const override {
    return std::make_unique<BulletSimulation>(scene, dt);
  }
};

}  // namespace

}  // namespace bb

extern "C" bb::Backend* beachball_create_backend() {
  return new bb::BulletBackend();
}
