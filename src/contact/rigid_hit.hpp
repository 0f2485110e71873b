// Newton's restitution between two rigid bodies at one contact point: the impulse that
// reverses e times the closing speed of the two surface points, with both bodies' spin and
// inertia taken into account,
//   j = -(1 + e) v_rel.n / (1/m1 + 1/m2 + n.((J1^-1 (r1 x n)) x r1) + n.((J2^-1 (r2 x n)) x r2)),
// which in 2D with a point ball is 1/m1 + 1/m2 + (r x n)^2 / J. It keeps momentum, and
// angular momentum about any point. The reference resolves every contact with it, and the
// course's `impulse` rule (seed section 5, beside the seed's plank shortcut) too.
#pragma once

#include <Eigen/Geometry>

#include "model/world.hpp"

namespace bb::contact {

/// What a hit changes on one body: mass (0: fixed, it never moves), inertia about its
/// centre in the world frame, centre, velocity and spin (world frame).
struct HitBody {
  double mass = 0.0;
  Eigen::Matrix3d inertia = Eigen::Matrix3d::Identity();
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();
  Eigen::Vector3d spin = Eigen::Vector3d::Zero();
};

/// `body` of the scene at a given state (a fixed body has mass 0 here). A point's or
/// sphere's zero inertia is kept: an impulse through its centre cannot turn it.
HitBody hit_body(const Body& body, const Eigen::Vector3d& position,
                 const Eigen::Quaterniond& orientation, const Eigen::Vector3d& velocity,
                 const Eigen::Vector3d& spin);

/// Newton's restitution at `point`, `normal` from body b towards body a; nothing happens
/// when they separate there. Returns the impulse j (N s) on a along the normal.
double impulse_hit(HitBody& a, HitBody& b, const Eigen::Vector3d& point,
                   const Eigen::Vector3d& normal, double restitution);

/// Coulomb's law at the same impact, after the normal impulse `normal_impulse` (N s, from
/// impulse_hit): the tangential impulse that stops the surface points slipping, if it is
/// at most mu_static times the normal impulse; else mu_kinetic times it, against the slip.
/// Exact where the normal and tangential directions do not couple (a ball against anything
/// through its centre: a sphere's arm lies along the normal). Returns the tangential
/// impulse's size (N s).
double friction_hit(HitBody& a, HitBody& b, const Eigen::Vector3d& point,
                    const Eigen::Vector3d& normal, double normal_impulse, double mu_static,
                    double mu_kinetic);

/// The spin a torque impulse `angular` (N m s) gives `body`: J^-1 (J omega + angular).
Eigen::Vector3d spun(const HitBody& body, const Eigen::Vector3d& angular);

/// Total linear momentum (N s), angular momentum about `origin` (N m s) and kinetic energy
/// (J, with the spin's part) of the moving bodies among a and b, for checking a hit.
Eigen::Vector3d momentum(const HitBody& a, const HitBody& b);
Eigen::Vector3d angular_momentum(const HitBody& a, const HitBody& b, const Eigen::Vector3d& origin);
double kinetic_energy(const HitBody& a, const HitBody& b);

}  // namespace bb::contact
