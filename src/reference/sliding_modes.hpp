// Coulomb's stick and slip for the reference (seed section 6, solved exactly): a body
// resting on a ground with friction is either stuck, held by static friction, or sliding
// along a fixed direction against kinetic friction mu_k N. Each mode is a smooth ODE; the
// switch between them is an event located where the sliding speed reaches zero, and the
// static coefficient decides there whether the body stays or slips on.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "model/world.hpp"

namespace bb {

/// m/s: a speed along the ground's normal this small is rounding, not motion (a velocity
/// along a slope written to 17 digits is 1e-17 off it): a body touching the ground with no
/// more starts at rest on it.
inline constexpr double kRestingNormalSpeed = 1e-12;

enum class SlideMode {
  Free,     ///< not resting on a ground with friction
  Stuck,    ///< static friction holds it: no tangential acceleration
  Sliding,  ///< kinetic friction against a fixed direction of sliding
};

/// What a body resting on the ground does next, from its velocity `v` and the acceleration
/// `a` the other forces give it (gravity, air, springs), on the plane with unit normal `n`.
struct SlideDecision {
  SlideMode mode = SlideMode::Free;
  Eigen::Vector3d direction = Eigen::Vector3d::Zero();  ///< unit, when sliding
};

/// Sliding when the velocity has a part along the plane (along it); at rest, stuck while
/// the tangential force is at most mu_s N, else sliding along that force. Throws
/// BeyondExactAnswer when the body would slide across the force along the plane (a path
/// that curves, which the reference does not model).
SlideDecision decide_slide(double mu_static, const Eigen::Vector3d& n, const Eigen::Vector3d& v,
                           const Eigen::Vector3d& a, const std::string& body, double t);

/// Why a box on the ground may tip over an edge during the run ("" when it cannot): the
/// friction at its face, h below its centre, tips it once h F_t / N exceeds its smallest
/// half width across the normal; F_t / N is mu_k while it slides and tan(slope) while it
/// is held.
std::string tipping_reason(const World& scene, const Body& box);

/// Why the reference cannot follow moving box `box` of `scene` exactly ("" when it can): it
/// must start flat on a face on the ground, at rest along the normal (within
/// kRestingNormalSpeed) and without spin,
/// touch nothing else, hang on no spring, be pushed only through its centre along the
/// ground, and not tip (tipping_reason).
std::string box_slide_reason(const World& scene, int box);

}  // namespace bb
