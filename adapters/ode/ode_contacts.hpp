// Contacts in ODE, set up the way its users do: geoms in a space, dSpaceCollide each step,
// and a near callback that makes a contact joint for every point dCollide finds between
// two geoms that may touch, with the surface the case gives that pair (ODE has no rule of
// its own to combine two bodies' materials: the callback sets each contact's surface).
#pragma once

#include <ode/ode.h>

#include <vector>

#include "model/world.hpp"

namespace bb {

/// Whether the scene has anything to touch: a ground or a [[contact]].
bool scene_has_contacts(const World& scene);

/// Most contact points dCollide is asked for per pair of geoms.
inline constexpr int kOdeMaxContactsPerPair = 4;

/// The surface of one pair of things that may touch.
struct OdeSurface {
  bool touches = false;
  dReal restitution = 0;
  dReal friction = 0;  ///< ODE's one Coulomb coefficient: engine_friction()
};

/// How ODE's contact friction works with the surface the near callback sets, for
/// engine_settings. Each contact point has two friction rows along t1 and t2 =
/// dPlaneSpace(normal) (no dContactFDir1): for a normal with |n_z| <= 1/sqrt(2),
/// t1 = (-n_y, n_x, 0) / |.| and t2 = n x t1 (up to sign), so on level ground x and z, on a
/// slope about z the slope line and z. Each row is bounded on its own by mu N
/// (dContactApprox1): a pyramid, not a cone, so a slide at 45 degrees to those axes meets up
/// to sqrt(2) mu N and stops in 1/sqrt(2) of the distance. A 2D case (motion in x-y, slopes
/// about z) always slides along an axis.
inline constexpr const char* kOdeFrictionModel =
    "dContactApprox1 on every contact with friction: each friction row bounded by mu x the "
    "point's normal force from the same solve (without it ODE bounds it by mu newtons, "
    "whatever the load); two rows per point (mu2 = mu), along dPlaneSpace(normal): x and z "
    "on level ground, the slope line and z on a slope about z; each bounded on its own, a "
    "friction pyramid: a slide along an axis meets mu N, a slide at 45 degrees to them up to "
    "sqrt(2) mu N and stops in 1/sqrt(2) of the distance (2D cases always slide along an "
    "axis)";

/// Geoms for the scene's bodies (a sphere or a box per body that can touch something) and
/// the ground plane, in one space; the near callback joins touching pairs each step.
class OdeContacts {
 public:
  /// `bodies` are the scene's bodies in order; `bounce_vel` is ODE's bouncing threshold.
  OdeContacts(const World& scene, dWorldID world, const std::vector<dBodyID>& bodies,
              dReal bounce_vel);
  ~OdeContacts();
  OdeContacts(const OdeContacts&) = delete;
  OdeContacts& operator=(const OdeContacts&) = delete;

  /// Finds this step's contacts and makes their joints; call before stepping the world.
  void collide();
  /// Removes this step's contact joints; call after stepping the world.
  void clear();
  /// Contact joints made over the run so far.
  long contacts_made() const { return contacts_made_; }

 private:
  static void near_callback(void* self, dGeomID a, dGeomID b);
  const OdeSurface& surface(int a, int b) const;

  dWorldID world_;
  dSpaceID space_;
  dJointGroupID joints_;
  dReal bounce_vel_;
  int count_;                         ///< bodies plus the ground, which is the last index
  std::vector<OdeSurface> surfaces_;  ///< count_ x count_
  long contacts_made_ = 0;
};

}  // namespace bb
