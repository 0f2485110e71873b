#include "bullet_hinges.hpp"

#include <string>

#include "bullet_vectors.hpp"

namespace bb {

BulletHingeJoints::BulletHingeJoints(const World& scene,
                                     const std::vector<std::unique_ptr<btRigidBody>>& bodies,
                                     btDynamicsWorld& world)
    : world_(world) {
  for (const Hinge& h : scene.hinges) {
    // A fixed body turns about nothing (Bullet would tie two static bodies together).
    if (scene.bodies[static_cast<std::size_t>(h.body)].fixed) continue;
    btRigidBody& body = *bodies[static_cast<std::size_t>(h.body)];
    const btTransform& frame = body.getWorldTransform();
    const btVector3 pivot_in_body = frame.invXform(to_bt(h.anchor));
    const btVector3 axis_in_body = frame.getBasis().transpose() * to_bt(h.axis);
    auto joint = std::make_unique<btHingeConstraint>(body, pivot_in_body, axis_in_body);
    // Bullet's defaults, stated: no motor, no limit (btAngularLimit's half range -1).
    joint->enableAngularMotor(false, 0, 0);
    world_.addConstraint(joint.get(), true);
    joints_.push_back(std::move(joint));
  }
}

BulletHingeJoints::~BulletHingeJoints() {
  for (auto& joint : joints_) world_.removeConstraint(joint.get());
}

void BulletHingeJoints::add_settings(Settings& out) const {
  // What the first joint holds, read back from Bullet (every joint is built alike).
  bool limit = false, motor = false, own_erp_cfm = false;
  for (const auto& joint : joints_) {
    limit = limit || joint->hasLimit();
    motor = motor || joint->getEnableAngularMotor();
    own_erp_cfm = own_erp_cfm || joint->getFlags() != 0;
  }
  const btContactSolverInfo& info = world_.getSolverInfo();
  out.push_back(
      {"hinge",
       std::string("btHingeConstraint(body, pivotInA, axisInA) per hinge: the body against "
                   "Bullet's fixed body, pivot = the anchor and axis in the body's frame at the "
                   "start, added with addConstraint (no collision between the two); limit ") +
           (limit ? "on" : "off") + ", motor " + (motor ? "on" : "off") +
           "; the joint's own ERP/CFM " +
           (own_erp_cfm ? "set (BT_HINGE_FLAGS)"
                        : "not set (no BT_HINGE_FLAGS): its rows take the solver's ERP "
                          "(btContactSolverInfo::m_erp, Baumgarte, no split impulse for joints) "
                          "and global CFM") +
           "; frame offset " + (joints_.empty() || joints_[0]->getUseFrameOffset() ? "on" : "off") +
           " (Bullet's default)"});
  out.push_back({"hinge_erp", double(info.m_erp)});
  out.push_back({"hinge_cfm", double(info.m_globalCfm)});
}

}  // namespace bb
