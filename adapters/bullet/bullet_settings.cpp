#include "bullet_settings.hpp"

#include <algorithm>
#include <string>

#include "../engine_friction.hpp"
#include "bullet_engine.hpp"
#include "seam/engine_keys.hpp"

namespace bb {

namespace {

double key(const EngineTables& engines, const char* name) {
  return engine_setting(engines, bullet_description(), name);
}

/// Appends `<name>_min` and `<name>_max` of `values` (0 when there are none).
void add_range(const std::string& name, const std::vector<double>& values, Settings& out) {
  const auto [lo, hi] = std::minmax_element(values.begin(), values.end());
  out.push_back({name + "_min", values.empty() ? 0.0 : *lo});
  out.push_back({name + "_max", values.empty() ? 0.0 : *hi});
}

}  // namespace

void configure_solver(const EngineTables& engines, btContactSolverInfo& info) {
  info.m_numIterations = static_cast<int>(key(engines, "solver_iterations"));
  info.m_erp = btScalar(key(engines, "erp"));
  info.m_erp2 = btScalar(key(engines, "contact_erp"));
  info.m_splitImpulse = key(engines, "split_impulse") != 0.0;
  info.m_splitImpulsePenetrationThreshold = -btScalar(key(engines, "split_impulse_depth"));
  info.m_restitutionVelocityThreshold = btScalar(key(engines, "restitution_velocity_threshold"));
  if (key(engines, "warm_starting") != 0.0)
    info.m_solverMode |= SOLVER_USE_WARMSTARTING;
  else
    info.m_solverMode &= ~SOLVER_USE_WARMSTARTING;
  // Friction as Bullet does it by default, set explicitly: one friction row per contact
  // point, along that point's sliding velocity, recomputed every step (no second direction,
  // no caching, no fixed directions), solved after all the normal rows in a fixed order.
  info.m_solverMode &=
      ~(SOLVER_USE_2_FRICTION_DIRECTIONS | SOLVER_ENABLE_FRICTION_DIRECTION_CACHING |
        SOLVER_DISABLE_VELOCITY_DEPENDENT_FRICTION_DIRECTION |
        SOLVER_INTERLEAVE_CONTACT_AND_FRICTION_CONSTRAINTS | SOLVER_RANDMIZE_ORDER);
  // Bullet's defaults, set here so that a change of default cannot pass unnoticed.
  info.m_warmstartingFactor = btScalar(0.85);
  info.m_linearSlop = 0;
  info.m_globalCfm = 0;
}

void add_contact_settings(const World& scene, const EngineTables& engines,
                          const btContactSolverInfo& info, const ShapeFigures& shapes,
                          const PlaneMultipoint& multipoint, Settings& out) {
  using S = std::string;
  out.push_back(
      {"collision", S("Bullet's own detection: btSphereShape, btBoxShape, btStaticPlaneShape for "
                      "the ground; only the pairs [ground] and [[contact]] name "
                      "(btOverlapFilterCallback on the pair cache); point bodies: btEmptyShape, "
                      "never paired")});
  out.push_back({"restitution_rule",
                 S("Bullet multiplies the two objects' restitutions and frictions "
                   "(btManifoldResult::calculateCombinedRestitution, "
                   "calculateCombinedFriction); the adapter sets each contact point's "
                   "m_combinedRestitution and m_combinedFriction to its pair's case value in "
                   "gContactAddedCallback (CF_CUSTOM_MATERIAL_CALLBACK on every object; the "
                   "ground's own restitution and friction are 1)")});
  add_friction_settings(scene, out);
  out.push_back(
      {"friction_model",
       S("one friction row per contact point, along the relative sliding velocity at that "
         "point at the start of the solve, gravity's increment included, bounded by mu x the "
         "point's normal impulse: isotropic Coulomb, a slide in any direction stops alike; "
         "SOLVER_USE_2_FRICTION_DIRECTIONS, direction caching and interleaving off "
         "(btSequentialImpulseConstraintSolver::convertContact, Bullet's default). A point "
         "slower than sqrt(SIMD_EPSILON) (1.5e-8 m/s in double, 3.5e-4 m/s in float) gets "
         "its row along the first direction of btPlaneSpace1(normal) (x on level ground) and "
         "none across it, so bullet-float may keep a crawl below 3.5e-4 m/s along z after a "
         "stop (5.5e-5 m/s after a slide at 45 degrees)")});
  out.push_back(
      {"plane_convex_multipoint",
       S("btDefaultCollisionConfiguration::setPlaneConvexMultipointIterations(iterations, "
         "threshold): while a box's manifold against the ground plane holds fewer than "
         "threshold points, iterations more queries with the box tilted slightly, the tilts "
         "spread around the normal, find its other corners in the same step. 6 and 5 when a "
         "moving box can touch the ground: a query every step (5 is above the manifold's 4 "
         "points, and last step's points still count when the threshold is checked), 6 tilts "
         "find all four corners of a face at any yaw; Bullet's suggested 3 and 3 left a "
         "sliding box on one point in 26 of 180 steps, sinking 7.6 mm and stopping at 2.470 m "
         "instead of 2.507 m; without any, a box rocks on one corner at a time and sinks 2 cm "
         "while sliding. Bullet's default 1 and 0 (off) otherwise")});
  out.push_back({"plane_convex_multipoint_iterations", double(multipoint.iterations)});
  out.push_back({"plane_convex_multipoint_threshold", double(multipoint.threshold)});
  out.push_back({"restitution_below_threshold",
                 S("zero restitution when the normal approach speed at the start of the step "
                   "is below restitution_velocity_threshold "
                   "(btSequentialImpulseConstraintSolver::restitutionCurve)")});
  out.push_back({"penetration_recovery",
                 S("a penetration shallower than split_impulse_depth is "
                   "pushed out through the velocity (contact_erp x depth / dt, which adds "
                   "bounce height); a deeper one by the split impulse, which moves the body "
                   "without changing its velocity; a contact point with a gap d targets the "
                   "normal speed e v - d / dt")});
  out.push_back({"collision_margin",
                 S("sphere: its radius (btSphereShape); box: 0.04 m, or a tenth of its "
                   "smallest half extent if less (btBoxShape::setSafeMargin), faces at the "
                   "half extents; ground plane: 0")});
  add_range("collision_margin", shapes.margins, out);
  out.push_back({"contact_breaking_threshold",
                 S("0.02 x the smaller shape's bounding radius (gContactBreakingThreshold, "
                   "relative): contact points against a plane or box start within that gap, "
                   "sphere-sphere points only on overlap")});
  add_range("contact_breaking_threshold", shapes.breaking_thresholds, out);
  out.push_back({"contact_processing_threshold",
                 S("BT_LARGE_FLOAT: every contact point goes to the solver")});
  out.push_back({"warm_starting_factor", double(info.m_warmstartingFactor)});
  out.push_back({"linear_slop", double(info.m_linearSlop)});
  out.push_back({"global_cfm", double(info.m_globalCfm)});
  if (engine_setting(engines, bullet_description(), "ccd") != 0.0)
    out.push_back(
        {"ccd_contacts", S("a CCD contact (createPredictiveContacts) gets restitution 0 and the "
                           "product of the frictions")});
}

}  // namespace bb
