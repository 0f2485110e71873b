// ODE as a plugin of two backends, double precision: `ode`, whose springs are ODE joints
// made soft by ERP and CFM, and `ode/force`, whose springs are forces added before each step.
#include <ode/ode.h>

#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <mutex>
#include <vector>

#include "../described_backend.hpp"
#include "../engine_friction.hpp"
#include "../point_body.hpp"
#include "ode_contacts.hpp"
#include "ode_engine.hpp"
#include "ode_hinges.hpp"
#include "physics/step_start.hpp"
#include "seam/engine_catalogue.hpp"
#include "seam/engine_keys.hpp"
#include "seam/plugin_api.hpp"

namespace bb {

namespace {

/// ODE's fatal errors and debug checks: said on stderr, which the runner's child process
/// captures into the run's reason, then the run ends as ODE requires.
[[noreturn]] void ode_fatal(int number, const char* message, va_list args) {
  char text[1024];
  std::vsnprintf(text, sizeof text, message, args);
  std::fprintf(stderr, "ODE error %d: %s\n", number, text);
  std::fflush(stderr);
  std::abort();
}

/// ODE's warnings: said on stderr, and the run goes on.
void ode_message(int number, const char* message, va_list args) {
  char text[1024];
  std::vsnprintf(text, sizeof text, message, args);
  std::fprintf(stderr, "ODE message %d: %s\n", number, text);
}

/// What dBodySetGyroscopicMode(body, 1) does in ODE 0.16 (dxStepIsland_Stage0_Bodies in
/// step.cpp, and the same in quickstep.cpp), for engine_settings.
constexpr const char* kOdeGyroscopicOn =
    "dBodySetGyroscopicMode(body, 1) on every moving body (ODE's default, set explicitly): "
    "before each step a torque replaces w x I w so that the step's semi-implicit update "
    "gives the spin of a linearly implicit Euler step, I w' + h w' x L = L with L = I w "
    "at the step's start (Lacoursiere 2006; one 3x3 inverse, no iteration), in dWorldStep "
    "and dWorldQuickStep alike; stable, but while the spin is not along L each step adds "
    "h^2 |w' x L|^2 / (2 |L|) to |L| and takes energy, sending a body off the separatrix "
    "towards its major axis: spinning_box at 1/60 s starts to turn over, then spins about "
    "its major axis (|L| +5%, energy -10%) and never flips; at 1/960 s it flips 10 times to "
    "the reference's 4";
/// ODE's own default CFM in this build, read from a new world (dWorldGetCFM): 1e-10 in double
/// precision, 1e-5 in single. The case's `cfm` (beachball's default 1e-5) replaces it.
double ode_own_cfm() {
  const dWorldID world = dWorldCreate();
  const double cfm = dWorldGetCFM(world);
  dWorldDestroy(world);
  return cfm;
}

constexpr const char* kOdeGyroscopicOff =
    "dBodySetGyroscopicMode(body, 0) on every moving body (gyroscopic_term = false): no "
    "gyroscopic torque, a free body keeps its world angular velocity and never flips";

/// What holds a 2D scene's moving bodies in the plane, for engine_settings.
constexpr const char* kOdePlane2d =
    "after each step every moving body without a hinge (a hinge about z holds its body "
    "already) is put back in the plane: z and the velocity's z part to 0, the quaternion "
    "keeps only w and z (renormalised) and the spin only its z part, the realignment ODE's "
    "demo_plane2d does after each step; no dJointCreatePlane2D, whose three rows per body "
    "made dWorldStep 6.8 times slower on an 8 x 8 spring sheet (its cost grows with the "
    "cube of the rows)";

/// Whether body `index` of `scene` turns on a hinge.
bool hinged(const World& scene, std::size_t index) {
  for (const Hinge& h : scene.hinges)
    if (static_cast<std::size_t>(h.body) == index) return true;
  return false;
}

Vec3 from_ode(const dReal* v) {
  return {v[0], v[1], v[2]};
}

class OdeSimulation : public Simulation {
 public:
  OdeSimulation(const World& scene, const EngineTables& engines, double dt, SpringsAs springs)
      : scene_(scene),
        engines_(engines),
        springs_(springs),
        dt_(dt),
        start_(scene, dt, {springs == SpringsAs::Forces}),
        world_(dWorldCreate()),
        threading_(dThreadingAllocateSelfThreadedImplementation()) {
    // ODE's default stepping context is one shared object; worlds stepped on different
    // threads each need their own.
    dWorldSetStepThreadingImplementation(world_, dThreadingImplementationGetFunctions(threading_),
                                         threading_);
    quick_step_ = engine_setting(engines, ode_description(), "quick_step") != 0.0;
    // dWorldQuickStep reorders its rows by ODE's one process-wide random sequence: every run
    // starts it where a new process does, whatever ran before it in this process.
    dRandSetSeed(0);
    gyroscopic_ = engine_setting(engines, ode_description(), "gyroscopic_term") != 0.0;
    dWorldSetGravity(world_, scene.gravity.x(), scene.gravity.y(), scene.gravity.z());
    dWorldSetERP(world_, engine_setting(engines, ode_description(), "erp"));
    dWorldSetCFM(world_, engine_setting(engines, ode_description(), "cfm"));
    dWorldSetQuickStepNumIterations(
        world_,
        static_cast<int>(engine_setting(engines, ode_description(), "quick_step_iterations")));
    dWorldSetLinearDamping(world_, engine_setting(engines, ode_description(), "linear_damping"));
    dWorldSetAngularDamping(world_, engine_setting(engines, ode_description(), "angular_damping"));
    dWorldSetAutoDisableFlag(world_, 0);
    for (const Body& b : scene.bodies) {
      // No contacts in the scene: no space, no geoms, only bodies.
      dBodyID body = dBodyCreate(world_);
      dBodySetPosition(body, b.position.x(), b.position.y(), b.position.z());
      const dQuaternion q = {b.orientation.w(), b.orientation.x(), b.orientation.y(),
                             b.orientation.z()};
      dBodySetQuaternion(body, q);
      if (b.fixed) {
        dBodySetKinematic(body);
      } else {
        // A point body is a small sphere here: ODE refuses a zero inertia (dMassCheck).
        const Vec3 inertia = engine_inertia(b);
        dMass mass;
        dMassSetParameters(&mass, b.mass, 0, 0, 0, inertia.x(), inertia.y(), inertia.z(), 0, 0, 0);
        dBodySetMass(body, &mass);
        dBodySetLinearVel(body, b.velocity.x(), b.velocity.y(), b.velocity.z());
        dBodySetAngularVel(body, b.angular_velocity.x(), b.angular_velocity.y(),
                           b.angular_velocity.z());
        dBodySetGyroscopicMode(body, gyroscopic_ ? 1 : 0);
        // A 2D scene stays in the x-y plane (realign_to_plane); a hinged body is left to its
        // hinge, about z in a 2D scene.
        if (scene.dims == 2 && !hinged(scene, bodies_.size())) planar_.push_back(body);
      }
      dBodySetAutoDisableFlag(body, 0);
      bodies_.push_back(body);
    }
    // Contacts: ODE's own geoms and detection, only when the scene has something to touch.
    if (scene_has_contacts(scene)) {
      dWorldSetContactSurfaceLayer(
          world_, engine_setting(engines, ode_description(), "contact_surface_layer"));
      contacts_ = std::make_unique<OdeContacts>(
          scene, world_, bodies_, engine_setting(engines, ode_description(), "bounce_vel"));
    }
    if (springs_ == SpringsAs::Joints) make_spring_joints();
    make_ode_hinges(scene, world_, bodies_);
  }
  ~OdeSimulation() override {
    contacts_.reset();
    dWorldDestroy(world_);
    dThreadingFreeImplementation(threading_);
  }
  OdeSimulation(const OdeSimulation&) = delete;
  OdeSimulation& operator=(const OdeSimulation&) = delete;

  void step() override {
    // Impulses due at the start of this step change velocities (and spins) at once; then
    // the force model's loads from the engine's own current state, as a game would add them.
    start_.impulses_due([this](const Impulse& imp) { push(imp); });
    if (start_.has_loads()) {
      read(state_);
      const Loads& loads = start_.loads(state_);
      for (std::size_t i = 0; i < bodies_.size(); ++i) {
        if (scene_.bodies[i].fixed) continue;
        const Vec3 &f = loads.force[i], &t = loads.torque[i];
        dBodyAddForce(bodies_[i], f.x(), f.y(), f.z());
        if (start_.torques()) dBodyAddTorque(bodies_[i], t.x(), t.y(), t.z());
      }
    }
    if (contacts_) contacts_->collide();
    if (quick_step_)
      dWorldQuickStep(world_, dt_);
    else
      dWorldStep(world_, dt_);
    if (contacts_) contacts_->clear();
    if (scene_.dims == 2) realign_to_plane();
  }

  void read(State& out) const override {
    for (std::size_t i = 0; i < bodies_.size(); ++i) {
      const dReal* q = dBodyGetQuaternion(bodies_[i]);
      out[i] = {from_ode(dBodyGetPosition(bodies_[i])),
                from_ode(dBodyGetLinearVel(bodies_[i])),
                {q[0], q[1], q[2], q[3]},
                from_ode(dBodyGetAngularVel(bodies_[i]))};
    }
  }

  Settings settings() const override {
    Settings s = engine_key_settings(engines_, ode_description());
    s.push_back({"precision", std::string(sizeof(dReal) == 8 ? "double" : "float")});
    // The world's cfm above is beachball's choice; ODE's own, for comparison.
    s.push_back({"cfm_ode_default", ode_own_cfm()});
    s.push_back({"auto_disable", false});
    s.push_back({"gyroscopic", std::string(gyroscopic_ ? kOdeGyroscopicOn : kOdeGyroscopicOff)});
    if (!contacts_) {
      s.push_back({"collision", std::string("none (no space, no geoms)")});
    } else {
      s.push_back(
          {"collision", std::string("ODE's own detection (dSpaceCollide on a simple space): a "
                                    "sphere or box geom per body that can touch, a plane for the "
                                    "ground; up to ") +
                            std::to_string(kOdeMaxContactsPerPair) + " contact points per pair"});
      s.push_back(
          {"detection",
           std::string("discrete: a contact exists only once the shapes overlap at the start "
                       "of a step (no continuous collision detection), so a bounce is found a "
                       "step late and from some penetration; a box gets a contact at each "
                       "corner at or below the plane (dCollideBoxPlane; the fourth only "
                       "below), so a box placed exactly on a slope starts on the corners "
                       "rounding puts there and may pivot or fall for a step (a box at rest on "
                       "28 degrees then slides 1.8 cm/s faster, 5% further in 3 s)")});
      s.push_back({"restitution_rule",
                   std::string("ODE combines nothing: each contact takes the surface its near "
                               "callback sets; the adapter sets the case's pair restitution "
                               "(dContactBounce) and friction (friction_rule) as mu on every "
                               "point")});
      add_friction_settings(scene_, s);
      s.push_back({"friction_model", std::string(kOdeFrictionModel)});
      s.push_back({"restitution_below_threshold",
                   std::string("a contact approaching slower than bounce_vel does not bounce")});
      s.push_back({"contact_erp_cfm", std::string("contacts use the world's erp and cfm "
                                                  "(no dContactSoftERP / dContactSoftCFM)")});
      s.push_back({"max_correcting_vel",
                   std::string("infinite (ODE's default; dWorldSetContactMaxCorrectingVel not "
                               "called)")});
      s.push_back({"contacts_made", static_cast<double>(contacts_->contacts_made())});
    }
    if (!scene_.springs.empty() && springs_ == SpringsAs::Forces)
      s.push_back({"springs", std::string("force k (l - L) + c (v_b - v_a).u along each spring, "
                                          "added with dBodyAddForce before each step")});
    if (!scene_.springs.empty() && springs_ == SpringsAs::Joints) {
      s.push_back(
          {"springs", std::string("a distance joint (dJointCreateDBall) per spring at the rest "
                                  "length, made soft as the ODE manual says: ERP = h k / (h k + "
                                  "c), CFM = 1 / (h k + c) per joint, h the step")});
      s.push_back({"spring_erp_first", spring_erp_});
      s.push_back({"spring_cfm_first", spring_cfm_});
    }
    if (!scene_.hinges.empty()) add_ode_hinge_settings(world_, s);
    if (!scene_.impulses.empty())
      s.push_back({"impulse", std::string("velocity set directly at the start of the step: "
                                          "v += J / m, omega += I_world^-1 (r x J) "
                                          "(ODE has no impulse call)")});
    add_point_body_setting(scene_, s);
    s.push_back({"plane_2d", std::string(scene_.dims == 2 ? kOdePlane2d : "none (3D scene)")});
    return s;
  }

 private:
  /// Puts each planar body back in the x-y plane after a step: z and its velocity to 0, the
  /// turn about z only (as ODE's demo_plane2d realigns a body on a plane-2D joint), the spin
  /// about z only.
  void realign_to_plane() {
    for (dBodyID body : planar_) {
      const dReal* x = dBodyGetPosition(body);
      dBodySetPosition(body, x[0], x[1], 0);
      const dReal* v = dBodyGetLinearVel(body);
      dBodySetLinearVel(body, v[0], v[1], 0);
      const dReal* q = dBodyGetQuaternion(body);
      const dReal norm = std::sqrt(q[0] * q[0] + q[3] * q[3]);
      const dQuaternion upright = {q[0] / norm, 0, 0, q[3] / norm};
      dBodySetQuaternion(body, upright);
      const dReal* w = dBodyGetAngularVel(body);
      dBodySetAngularVel(body, 0, 0, w[2]);
    }
  }

  std::vector<dBodyID> planar_;  ///< moving, unhinged bodies of a 2D scene
  const World& scene_;
  const EngineTables& engines_;  ///< the case's [engines.ode] table among the others
  SpringsAs springs_;            ///< ode: ODE's joints; ode/force: forces
  dReal dt_;
  StepStart start_;  ///< impulses due and the force model's loads
  bool quick_step_ = false;
  bool gyroscopic_ = true;  ///< dBodySetGyroscopicMode of every moving body
  dWorldID world_;
  dThreadingImplementationID threading_;
  std::vector<dBodyID> bodies_;
  State state_{scene_.bodies.size()};  ///< read before each step for the forces
  std::unique_ptr<OdeContacts> contacts_;
  double spring_erp_ = 0.0, spring_cfm_ = 0.0;  ///< of the first spring joint, for settings

  /// Each spring as a distance joint held at its rest length, softened into a spring of
  /// stiffness k and damping c by ERP and CFM (ODE manual, "Soft constraint and constraint
  /// force mixing": ERP = h k / (h k + c), CFM = 1 / (h k + c)).
  void make_spring_joints() {
    for (const Spring& spring : scene_.springs) {
      dJointID joint = dJointCreateDBall(world_, nullptr);
      dJointAttach(joint, bodies_[static_cast<std::size_t>(spring.body_a)],
                   bodies_[static_cast<std::size_t>(spring.body_b)]);
      const Vec3 a = scene_.bodies[static_cast<std::size_t>(spring.body_a)].position;
      const Vec3 b = scene_.bodies[static_cast<std::size_t>(spring.body_b)].position;
      dJointSetDBallAnchor1(joint, a.x(), a.y(), a.z());
      dJointSetDBallAnchor2(joint, b.x(), b.y(), b.z());
      dJointSetDBallDistance(joint, spring.rest_length);
      const double hk = dt_ * spring.stiffness;
      const double erp = hk / (hk + spring.damping), cfm = 1.0 / (hk + spring.damping);
      dJointSetDBallParam(joint, dParamERP, erp);
      dJointSetDBallParam(joint, dParamCFM, cfm);
      if (spring_cfm_ == 0.0) spring_erp_ = erp, spring_cfm_ = cfm;
    }
  }
  /// An impulse J at a point: v += J / m and omega += I_world^-1 (r x J).
  void push(const Impulse& imp) {
    const std::size_t i = static_cast<std::size_t>(imp.body);
    const Body& body = scene_.bodies[i];
    if (body.fixed) return;
    dBodyID b = bodies_[i];
    const Vec3 v = from_ode(dBodyGetLinearVel(b)) + imp.impulse / body.mass;
    dBodySetLinearVel(b, v.x(), v.y(), v.z());
    if (!imp.point) return;
    const Vec3 arm = *imp.point - from_ode(dBodyGetPosition(b));
    const dReal* q = dBodyGetQuaternion(b);
    const Eigen::Matrix3d inertia = engine_world_inertia(body, Quat(q[0], q[1], q[2], q[3]));
    const Vec3 w =
        from_ode(dBodyGetAngularVel(b)) + Vec3(inertia.ldlt().solve(arm.cross(imp.impulse)));
    dBodySetAngularVel(b, w.x(), w.y(), w.z());
  }
};

/// Starts a run with the springs as `springs`, ODE made ready first: once per process, and
/// once per thread that steps.
std::unique_ptr<Simulation> start_ode(const World& world, const BackendSettings& settings,
                                      double dt, SpringsAs springs) {
  static std::once_flag initialised;
  std::call_once(initialised, [] {
    dInitODE2(0);
    dSetErrorHandler(ode_fatal);
    dSetDebugHandler(ode_fatal);
    dSetMessageHandler(ode_message);
  });
  // ODE keeps per-thread data; each thread that steps a world must allocate it.
  dAllocateODEDataForThread(dAllocateMaskAll);
  return start_engine<OdeSimulation>(springs)(world, settings, dt);
}

/// How variant `springs` starts its runs.
DeclaredBackend::Start ode_start(SpringsAs springs) {
  return [springs](const World& world, const BackendSettings& settings, double dt) {
    return start_ode(world, settings, dt, springs);
  };
}

}  // namespace

}  // namespace bb

namespace {

/// The plugin's backends: the springs as ODE's joints, or as forces.
bb::Backend* ode_backend(int index) {
  static const std::vector<bb::VariantStart> starts = {
      {"ode", bb::ode_start(bb::SpringsAs::Joints)},
      {"ode/force", bb::ode_start(bb::SpringsAs::Forces)}};
  return bb::engine_backend(bb::ode_description(), {"ode", BB_ODE_VERSION}, starts, index);
}

}  // namespace

BEACHBALL_PLUGIN_BACKENDS(ode_backend)
