#include "box2d_hinges.hpp"

#include <string>

#include "box2d_vectors.hpp"

namespace bb {

void make_box2d_hinges(const World& scene, b2World& world, const std::vector<b2Body*>& bodies) {
  if (scene.hinges.empty()) return;
  // The world's side of every hinge: a static body at the origin, without fixtures.
  b2BodyDef ground_def;
  ground_def.type = b2_staticBody;
  ground_def.position.SetZero();
  b2Body* ground = world.CreateBody(&ground_def);
  for (const Hinge& h : scene.hinges) {
    b2Body* body = bodies[static_cast<std::size_t>(h.body)];
    if (body->GetType() == b2_staticBody) continue;
    b2RevoluteJointDef def;
    const b2Vec2 anchor = to_b2(h.anchor);
    def.bodyA = ground;
    def.bodyB = body;
    def.localAnchorA = ground->GetLocalPoint(anchor);
    def.localAnchorB = body->GetLocalPoint(anchor);
    def.referenceAngle = body->GetAngle() - ground->GetAngle();
    def.enableLimit = false;
    def.enableMotor = false;
    def.motorSpeed = 0.0f;
    def.maxMotorTorque = 0.0f;
    def.collideConnected = false;
    world.CreateJoint(&def);
  }
}

void add_box2d_hinge_settings(Settings& out) {
  out.push_back(
      {"hinge",
       std::string("b2RevoluteJoint per hinge: bodyA a static body at the origin (no fixtures), "
                   "bodyB the body, localAnchorA/B the world anchor in each body's frame, "
                   "referenceAngle the body's angle at the start; limit off, motor off "
                   "(enableLimit = enableMotor = false, maxMotorTorque 0); collideConnected "
                   "false. Box2D has no ERP or softness for it: the velocity iterations solve "
                   "the point rows, each position iteration removes the whole remaining "
                   "anchor error (nonlinear Gauss-Seidel, corrections capped at "
                   "b2_maxLinearCorrection 0.2 m) until it is under b2_linearSlop 0.005 m")});
}

}  // namespace bb
