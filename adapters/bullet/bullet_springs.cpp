#include "bullet_springs.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "bullet_engine.hpp"
#include "bullet_vectors.hpp"
#include "seam/engine_keys.hpp"

namespace bb {

namespace {

/// A rotation whose first column is `x` (a unit vector): x, then two perpendiculars.
btMatrix3x3 basis_along(const btVector3& x) {
  btVector3 y, z;
  btPlaneSpace1(x, y, z);
  return {x.x(), y.x(), z.x(), x.y(), y.y(), z.y(), x.z(), y.z(), z.z()};
}

/// Where a spring's constraint frame sits in a body's own coordinates: at its centre,
/// turned so that the frame's x axis is `world_basis`'s.
btTransform frame_in(const btRigidBody& body, const btMatrix3x3& world_basis) {
  btTransform frame;
  frame.setIdentity();
  frame.setBasis(body.getWorldTransform().getBasis().transpose() * world_basis);
  return frame;
}

}  // namespace

SpringRow bullet_spring_row(double stiffness, double damping, double mass_a, double mass_b,
                            double dt, bool limit_if_needed) {
  const double m = mass_a == 0.0   ? mass_b
                   : mass_b == 0.0 ? mass_a
                                   : mass_a * mass_b / (mass_a + mass_b);
  SpringRow row{stiffness, damping, false, false};
  if (limit_if_needed && 0.25 < std::sqrt(stiffness / m) * dt) {
    row.stiffness = m / (16.0 * dt * dt);
    row.stiffness_limited = true;
  }
  if (limit_if_needed && damping * dt > m) {
    row.damping = m / dt;
    row.damping_limited = true;
  }
  return row;
}

BulletSpringJoints::BulletSpringJoints(const World& scene, const EngineTables& engines, double dt,
                                       const std::vector<std::unique_ptr<btRigidBody>>& bodies,
                                       btDynamicsWorld& world)
    : world_(world),
      limit_if_needed_(engine_setting(engines, bullet_description(), "spring_limit_if_needed") !=
                       0.0) {
  for (const Spring& s : scene.springs) {
    const Body& a = scene.bodies[static_cast<std::size_t>(s.body_a)];
    const Body& b = scene.bodies[static_cast<std::size_t>(s.body_b)];
    // Between two anchors a spring moves nothing (Bullet would divide by two zero masses).
    if (a.fixed && b.fixed) continue;
    btRigidBody& body_a = *bodies[static_cast<std::size_t>(s.body_a)];
    btRigidBody& body_b = *bodies[static_cast<std::size_t>(s.body_b)];
    const btVector3 d = to_bt(b.position - a.position);
    const btVector3 along = d.length() > 0 ? d.normalized() : btVector3(1, 0, 0);
    const btMatrix3x3 basis = basis_along(along);
    auto joint = std::make_unique<btGeneric6DofSpring2Constraint>(
        body_a, body_b, frame_in(body_a, basis), frame_in(body_b, basis));
    // Lower above upper frees an axis (btTranslationalLimitMotor2::testLimitValue and
    // btRotationalLimitMotor2::testLimitValue): x keeps only its spring.
    joint->setLinearLowerLimit(btVector3(1, 1, 1));
    joint->setLinearUpperLimit(btVector3(-1, -1, -1));
    joint->setAngularLowerLimit(btVector3(1, 1, 1));
    joint->setAngularUpperLimit(btVector3(-1, -1, -1));
    joint->enableSpring(0, true);
    joint->setStiffness(0, btScalar(s.stiffness), limit_if_needed_);
    joint->setDamping(0, btScalar(s.damping), limit_if_needed_);
    joint->setEquilibriumPoint(0, btScalar(s.rest_length));
    world_.addConstraint(joint.get(), true);
    joints_.push_back(std::move(joint));
    rows_.push_back(bullet_spring_row(s.stiffness, s.damping, a.fixed ? 0.0 : a.mass,
                                      b.fixed ? 0.0 : b.mass, dt, limit_if_needed_));
  }
}

void BulletSpringJoints::aim() {
  for (const auto& joint : joints_) {
    const btRigidBody& a = joint->getRigidBodyA();
    const btRigidBody& b = joint->getRigidBodyB();
    const btVector3 d = b.getCenterOfMassPosition() - a.getCenterOfMassPosition();
    if (d.length2() == btScalar(0)) continue;
    const btMatrix3x3 basis = basis_along(d.normalized());
    joint->setFrames(frame_in(a, basis), frame_in(b, basis));
  }
}

BulletSpringJoints::~BulletSpringJoints() {
  for (auto& joint : joints_) world_.removeConstraint(joint.get());
}

void BulletSpringJoints::add_settings(Settings& out) const {
  using S = std::string;
  out.push_back(
      {"springs", S("btGeneric6DofSpring2Constraint per spring, frames at the two bodies' "
                    "centres with x from a to b; linear spring on x (stiffness k, damping c, "
                    "equilibrium point = rest length); y, z and every angular axis free (lower "
                    "limit above upper); collisions between the linked bodies disabled; "
                    "anchored particles static (mass 0)")});
  out.push_back(
      {"spring_axis", S("the spring pulls along frame a's x axis, which turns only with body a: "
                        "before each step both frames are aimed again along the line from a's "
                        "centre to b's (setFrames), so the spring acts along the current line "
                        "in every direction, that line held over the step as Bullet's solver "
                        "holds every row")});
  out.push_back({"spring_limit_if_needed", limit_if_needed_});
  out.push_back(
      {"spring_stiffness_limit",
       S(limit_if_needed_
             ? "limitIfNeeded (Bullet's default): where sqrt(k / m) dt > 0.25 Bullet uses "
               "k = m / (16 dt^2), and where c dt > m it uses c = m / dt, m the pair's reduced "
               "mass or the moving body's mass (btGeneric6DofSpring2Constraint.cpp:852-860); "
               "the values below follow that rule"
             : "off: every spring gets the case's k and c, however stiff")});
  // The stiffness and damping Bullet applies, by its rule, over all springs.
  double k_min = 0, k_max = 0, c_max = 0, stiff = 0, damped = 0;
  for (std::size_t i = 0; i < rows_.size(); ++i) {
    const SpringRow& r = rows_[i];
    k_min = i == 0 ? r.stiffness : std::min(k_min, r.stiffness);
    k_max = std::max(k_max, r.stiffness);
    c_max = std::max(c_max, r.damping);
    stiff += r.stiffness_limited ? 1.0 : 0.0;
    damped += r.damping_limited ? 1.0 : 0.0;
  }
  out.push_back({"spring_stiffness_used_min", k_min});
  out.push_back({"spring_stiffness_used_max", k_max});
  out.push_back({"spring_damping_used_max", c_max});
  out.push_back({"springs_stiffness_limited", stiff});
  out.push_back({"springs_damping_limited", damped});
}

}  // namespace bb
