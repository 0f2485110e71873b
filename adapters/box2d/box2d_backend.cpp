// Box2D 2.4 as a backend: 2D scenes only, single precision.
#include <box2d/box2d.h>

#include <memory>
#include <vector>

#include "../point_body.hpp"
#include "scene/engine_keys.hpp"
#include "scene/external_forces.hpp"
#include "scene/plugin_api.hpp"

namespace bb {

namespace {

b2Vec2 to_b2(const Vec3& v) {
  return {float(v.x()), float(v.y())};
}

class Box2dSimulation : public Simulation {
 public:
  Box2dSimulation(const Scene& scene, double dt)
      : scene_(scene), dt_(float(dt)), world_(to_b2(scene.gravity)) {
    velocity_iterations_ = static_cast<int>(engine_setting(scene, "box2d", "velocity_iterations"));
    position_iterations_ = static_cast<int>(engine_setting(scene, "box2d", "position_iterations"));
    world_.SetAllowSleeping(false);
    for (const Body& b : scene.bodies) {
      b2BodyDef def;
      def.type = b.fixed ? b2_staticBody : b2_dynamicBody;
      def.position = to_b2(b.position);
      def.angle = float(angle_about_z(b.orientation));
      def.linearVelocity = to_b2(b.velocity);
      def.angularVelocity = float(b.angular_velocity.z());
      def.linearDamping = float(engine_setting(scene, "box2d", "linear_damping"));
      def.angularDamping = float(engine_setting(scene, "box2d", "angular_damping"));
      def.allowSleep = false;
      b2Body* body = world_.CreateBody(&def);
      // No contacts in the scene, so no fixtures: mass and inertia are set directly. A point
      // body gets a small sphere's inertia, as in every engine (point_body.hpp).
      if (!b.fixed) {
        b2MassData mass{float(b.mass), b2Vec2(0.0f, 0.0f), float(engine_inertia(b).z())};
        body->SetMassData(&mass);
      }
      bodies_.push_back(body);
    }
  }

  void step() override {
    // The harness's forces from the engine's own current state, as a game would add them.
    if (has_external_forces(scene_)) {
      read(state_);
      external_forces(scene_, state_, forces_);
      for (std::size_t i = 0; i < bodies_.size(); ++i)
        if (!scene_.bodies[i].fixed) bodies_[i]->ApplyForceToCenter(to_b2(forces_[i]), true);
    }
    world_.Step(dt_, velocity_iterations_, position_iterations_);
  }

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
    Settings s = engine_key_settings(scene_, "box2d");
    s.push_back({"precision", std::string("float")});
    s.push_back({"sleeping", false});
    s.push_back({"collision", std::string("none (no fixtures; mass set with SetMassData)")});
    add_point_body_setting(scene_, s);
    s.push_back({"max_translation", std::string("2 m per step (b2_maxTranslation, built in)")});
    s.push_back({"max_rotation", std::string("pi/2 rad per step (b2_maxRotation, built in)")});
    return s;
  }

 private:
  const Scene& scene_;
  float dt_;
  int velocity_iterations_ = 8;
  int position_iterations_ = 3;
  b2World world_;
  std::vector<b2Body*> bodies_;
  State state_{scene_.bodies.size()};  ///< read before each step for the forces
  std::vector<Vec3> forces_;
};

class Box2dBackend : public Backend {
 public:
  std::string name() const override { return "box2d"; }
  FeatureSet supports() const override {
    return {Feature::Gravity, Feature::Drag,     Feature::Magnus,
            Feature::Wind,    Feature::Rotation, Feature::Boxes};
  }
  std::pair<std::string, std::string> library_version() const override {
    const std::string header = std::to_string(b2_version.major) + "." +
                               std::to_string(b2_version.minor) + "." +
                               std::to_string(b2_version.revision);
    // The installed package's version; the library's b2_version lags behind in 2.4.1.
    const std::string package = BOX2D_PACKAGE_VERSION;
    if (package == header) return {"box2d", package};
    return {"box2d", package + " (its b2_version says " + header + ")"};
  }
  std::unique_ptr<Simulation> start(const Scene& scene, double dt) const override {
    return std::make_unique<Box2dSimulation>(scene, dt);
  }
};

}  // namespace

}  // namespace bb

extern "C" bb::Backend* beachball_create_backend() {
  return new bb::Box2dBackend();
}
