// MuJoCo as a plugin of three backends, one per integrator of MuJoCo's own (`mujoco`: Euler,
// `mujoco/rk4`, `mujoco/implicit`): the World written as MJCF (mujoco_model.hpp), loaded from
// memory, stepped with mj_step. Forces and torques of the force model go in through xfrc_applied
// before each step, as a game adds them; an impulse changes qvel at the step's start.
#include <mujoco/mujoco.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <mutex>
#include <string>
#include <string_view>
#include <tuple>
#include <utility>
#include <vector>

#include "../described_backend.hpp"
#include "../engine_friction.hpp"
#include "../point_body.hpp"
#include "kept_model.hpp"
#include "model/contact_pairs.hpp"
#include "mujoco_engine.hpp"
#include "mujoco_model.hpp"
#include "mujoco_warnings.hpp"
#include "physics/hinge_motion.hpp"
#include "physics/step_start.hpp"
#include "seam/engine_catalogue.hpp"
#include "seam/engine_keys.hpp"
#include "seam/plugin_api.hpp"

namespace bb {

namespace {

/// MuJoCo's errors: said on stderr, which the runner's child process captures into the
/// run's reason, then the run ends (MuJoCo's default would exit the program).
[[noreturn]] void mujoco_error(const char* message) {
  std::fprintf(stderr, "MuJoCo error: %s\n", message);
  std::fflush(stderr);
  std::abort();
}

/// MuJoCo's warnings: said on stderr, and the run goes on.
void mujoco_warning(const char* message) {
  std::fprintf(stderr, "MuJoCo warning: %s\n", message);
}

constexpr const char* kGyroscopicOn =
    "MuJoCo's bias force qfrc_bias (mj_rne: Coriolis and centrifugal forces, for a free body "
    "the gyroscopic torque -w x I w), evaluated at the step's start and stepped explicitly "
    "like every other force";
constexpr const char* kGyroscopicOff =
    "gyroscopic_term = false: the opposite torque w x I w added through xfrc_applied before "
    "each step cancels the bias force's gyroscopic part, so a free body keeps its world "
    "angular velocity and never flips";

/// How a run of MuJoCo's option integrator `integrator` steps, for engine_settings.
const char* integrator_text(std::string_view integrator) {
  return integrator == "RK4"
             ? "RK4 (option integrator): MuJoCo's classic fourth-order Runge-Kutta, each stage "
               "computing MuJoCo's own forces (gravity, contacts, joints, the bias force) again; "
               "the "
               "force model's forces go in through xfrc_applied once per step and are held over "
               "its "
               "four stages, as a game sets them"
         : integrator == "implicit"
             ? "implicit (option integrator): implicit in velocity, the derivative of MuJoCo's own "
               "velocity-dependent forces (the bias force's Coriolis and gyroscopic terms, "
               "damping) "
               "taken into the step; the positions then with the new velocities"
             : "Euler (MuJoCo's default, set explicitly): the new velocities first, then the "
               "positions with them";
}

constexpr const char* kHingeText =
    "a MuJoCo hinge joint (<joint type=\"hinge\">) per [[hinge]], the body's parent the world: "
    "one degree of freedom in reduced coordinates, so the anchor holds exactly (no constraint "
    "rows, no ERP or CFM to soften it); limit off, motor off, no joint damping, stiffness, "
    "friction loss or armature";

class MujocoSimulation : public Simulation {
 public:
  /// A run stepped by MuJoCo's option integrator `integrator` ("Euler", "RK4", "implicit").
  MujocoSimulation(const World& world, const EngineTables& engines, double dt,
                   std::string integrator)
      : world_(world),
        engines_(engines),
        integrator_(std::move(integrator)),
        dt_(dt),
        start_(world, dt, {false}),  // springs are MuJoCo tendons
        xml_(mujoco_model_xml(world, dt, integrator_)),
        gyroscopic_(engine_setting(engines, mujoco_description(), "gyroscopic_term") != 0.0) {
    std::tie(model_, data_) = kept_model().take(xml_);
    for (std::size_t i = 0; i < world.bodies.size(); ++i) {
      const Body& b = world.bodies[i];
      const int id = static_cast<int>(i) + 1;  // 0 is the world body
      qpos_.push_back(b.fixed ? -1 : model_->jnt_qposadr[model_->body_jntadr[id]]);
      dof_.push_back(b.fixed ? -1 : model_->body_dofadr[id]);
      hinges_.push_back(b.fixed ? nullptr : hinge_of(world, i));
      if (!b.fixed) set_state(i, b.position, b.orientation, b.velocity, b.angular_velocity);
    }
    mj_forward(model_, data_);
  }
  ~MujocoSimulation() override {
    kept_model().give_back(xml_, data_);
    mj_deleteModel(model_);
  }
  MujocoSimulation(const MujocoSimulation&) = delete;
  MujocoSimulation& operator=(const MujocoSimulation&) = delete;

  void step() override {
    start_.impulses_due([this](const Impulse& imp) { push(imp); });
    mju_zero(data_->xfrc_applied, 6 * model_->nbody);
    if (start_.has_loads() || !gyroscopic_) read(state_);
    const Loads* loads = start_.has_loads() ? &start_.loads(state_) : nullptr;
    for (std::size_t i = 0; i < world_.bodies.size(); ++i) {
      if (world_.bodies[i].fixed) continue;
      mjtNum* f = data_->xfrc_applied + 6 * (i + 1);
      Vec3 torque = Vec3::Zero();
      if (loads) {
        for (int k = 0; k < 3; ++k) f[k] = loads->force[i][k];
        if (start_.torques()) torque = loads->torque[i];
      }
      if (!gyroscopic_) torque += gyroscopic_torque(i);
      for (int k = 0; k < 3; ++k) f[3 + k] = torque[k];
    }
    mj_step(model_, data_);
    // A reset or a dropped contact shows in MuJoCo's warning counters, not in its state.
    warnings_.after_step(model_, data_, ++steps_);
  }

  std::vector<EngineIntervention> interventions() const override {
    return warnings_.interventions();
  }

  void read(State& out) const override {
    for (std::size_t i = 0; i < world_.bodies.size(); ++i) {
      const Body& b = world_.bodies[i];
      if (b.fixed) {
        out[i] = {b.position, Vec3::Zero(), b.orientation, Vec3::Zero()};
        continue;
      }
      const mjtNum* q = data_->qpos + qpos_[i];
      const mjtNum* v = data_->qvel + dof_[i];
      if (hinges_[i] != nullptr) {
        out[i] = hinged_state(b, *hinges_[i], q[0], v[0]);
      } else if (world_.dims == 3) {
        const Quat orientation(q[3], q[4], q[5], q[6]);
        // A free joint's angular velocity is in the body's frame.
        out[i] = {{q[0], q[1], q[2]},
                  {v[0], v[1], v[2]},
                  orientation,
                  orientation.normalized() * Vec3(v[3], v[4], v[5])};
      } else {
        out[i] = {{q[0], q[1], 0.0},
                  {v[0], v[1], 0.0},
                  Quat(Eigen::AngleAxisd(q[2], Vec3::UnitZ())),
                  {0.0, 0.0, v[2]}};
      }
    }
  }

  Settings settings() const override {
    Settings s = engine_key_settings(engines_, mujoco_description());
    s.push_back({"precision", std::string(sizeof(mjtNum) == 8 ? "double" : "float")});
    s.push_back({"integrator", std::string(integrator_text(integrator_))});
    std::string gyroscopic = gyroscopic_ ? kGyroscopicOn : kGyroscopicOff;
    if (!gyroscopic_ && integrator_ == "RK4")
      gyroscopic +=
          " (under RK4 the torque is held over the four stages while the bias force "
          "is computed again at each: it cancels the term at the step's start only, "
          "and the world spin drifts slowly)";
    s.push_back({"gyroscopic", gyroscopic});
    s.push_back({"forces", std::string("the force model's forces and torques through "
                                       "xfrc_applied at each body's centre, set before each "
                                       "step; gravity MuJoCo's own (option gravity)")});
    // MuJoCo's joint damping, as the other engines' built-in damping: none, its default.
    s.push_back({"linear_damping", 0.0});
    s.push_back({"angular_damping", 0.0});
    s.push_back({"fluid", std::string("option density 0 and viscosity 0: MuJoCo's own "
                                      "fluid forces off")});
    add_contact_settings(s);
    if (!world_.hinges.empty()) s.push_back({"hinge", std::string(kHingeText)});
    if (!world_.springs.empty())
      s.push_back({"springs", std::string("a MuJoCo spatial tendon per spring between sites at "
                                          "the bodies' centres, with the spring's stiffness, "
                                          "damping and rest length (springlength): MuJoCo's "
                                          "own passive force, computed at every stage of its "
                                          "step")});
    s.push_back(
        {"plane_2d", std::string(world_.dims == 2 ? "two slide joints (x, y) and a hinge (z) per "
                                                    "moving body: MuJoCo's own joints hold it in "
                                                    "the plane"
                                                  : "none (3D scene)")});
    if (!world_.impulses.empty())
      s.push_back({"impulse", std::string("qvel changed at the start of the step: v += J / m, "
                                          "omega += I_world^-1 (r x J) (MuJoCo has no "
                                          "impulse call)")});
    add_point_body_setting(world_, s);
    s.push_back({"bad_values",
                 std::string("a position, velocity or acceleration NaN or beyond 1e10 (mjMAXVAL): "
                             "MuJoCo warns (mjWARN_BADQPOS, BADQVEL, BADQACC) and resets its data "
                             "to the initial state; read from its warning counters after each "
                             "step and reported as a reset, the first one with its step")});
    s.push_back({"buffers", std::string("nconmax 100 contacts and njmax 500 constraint rows "
                                        "(MuJoCo 2.2.2's defaults): beyond them it drops what "
                                        "does not fit (mjWARN_CONTACTFULL, CNSTRFULL), reported "
                                        "as a cap")});
    return s;
  }

 private:
  /// A hinged body's state at angle `angle` (rad) from where it starts, turning at `rate`
  /// (rad/s): turned about the axis through the anchor.
  static BodyState hinged_state(const Body& b, const Hinge& h, double angle, double rate) {
    const Quat turn(Eigen::AngleAxisd(angle, h.axis));
    const Vec3 centre = h.anchor + turn * (b.position - h.anchor);
    const Vec3 spin = rate * h.axis;
    return {centre, spin.cross(centre - h.anchor), turn * b.orientation.normalized(), spin};
  }

  /// Sets body `i`'s joint positions and velocities from a world state (a hinged body: its
  /// turn rate only, as it starts).
  void set_state(std::size_t i, const Vec3& x, const Quat& q, const Vec3& v, const Vec3& w) {
    mjtNum* qpos = data_->qpos + qpos_[i];
    mjtNum* qvel = data_->qvel + dof_[i];
    if (hinges_[i] != nullptr) {
      qvel[0] = w.dot(hinges_[i]->axis);
    } else if (world_.dims == 3) {
      const Vec3 local = q.normalized().conjugate() * w;
      const mjtNum values[7] = {x.x(), x.y(), x.z(), q.w(), q.x(), q.y(), q.z()};
      std::copy(values, values + 7, qpos);
      const mjtNum speeds[6] = {v.x(), v.y(), v.z(), local.x(), local.y(), local.z()};
      std::copy(speeds, speeds + 6, qvel);
    } else {
      qpos[0] = x.x(), qpos[1] = x.y(), qpos[2] = 2.0 * std::atan2(q.z(), q.w());
      qvel[0] = v.x(), qvel[1] = v.y(), qvel[2] = w.z();
    }
  }

  /// w x I w of body `i` at the state read last, world frame: the torque that cancels the
  /// bias force's gyroscopic part.
  Vec3 gyroscopic_torque(std::size_t i) const {
    const BodyState& s = state_[i];
    const Eigen::Matrix3d inertia = engine_world_inertia(world_.bodies[i], s.orientation);
    return s.angular_velocity.cross(Vec3(inertia * s.angular_velocity));
  }

  /// An impulse J at a point: v += J / m and omega += I_world^-1 (r x J); on a hinge, the
  /// turn rate by J's moment about the axis over the inertia about it.
  void push(const Impulse& imp) {
    const std::size_t i = static_cast<std::size_t>(imp.body);
    const Body& body = world_.bodies[i];
    if (body.fixed) return;
    read(state_);
    BodyState s = state_[i];
    if (hinges_[i] != nullptr) {
      hinge_impulse(body, s.orientation, s.position, imp.impulse, imp.point.value_or(s.position),
                    *hinges_[i], s.velocity, s.angular_velocity);
      set_state(i, s.position, s.orientation, s.velocity, s.angular_velocity);
      return;
    }
    s.velocity += imp.impulse / body.mass;
    if (imp.point) {
      const Eigen::Matrix3d inertia = engine_world_inertia(body, s.orientation);
      s.angular_velocity += inertia.ldlt().solve((*imp.point - s.position).cross(imp.impulse));
    }
    set_state(i, s.position, s.orientation, s.velocity, s.angular_velocity);
  }

  /// How the contacts are built, and their numbers (the first pair's).
  void add_contact_settings(Settings& s) const {
    const std::vector<ContactPair> pairs = contact_pairs(world_);
    if (pairs.empty()) {
      s.push_back({"collision", std::string("none: nothing in the case can touch")});
      return;
    }
    s.push_back(
        {"collision",
         std::string("MuJoCo's own detection (mj_collision) of the bodies' sphere or box geoms "
                     "(and a plane geom for the ground), only in the <pair>s the adapter "
                     "writes, one per pair of the case (contype and conaffinity 0 "
                     "elsewhere); a point body has no geom and touches nothing")});
    s.push_back(
        {"contact_model",
         std::string("soft, as MuJoCo's contacts are: solref in the direct form (-k, -b), "
                     "the reference acceleration -b v - k x of a spring and damper with "
                     "k = 1 / tau^2 and b = 2 zeta / tau, solimp 0.9999 0.9999 0.001 0.5 "
                     "2 (the impedance at its largest, so that acceleration is "
                     "followed), margin 1e-6 m and gap 0 (a contact counts from 1 um apart, "
                     "so that a box placed exactly touching meets the ground with every "
                     "corner, whatever the rounding); condim 3 (sliding friction along both "
                     "tangents) where the pair has friction, else condim 1")});
    s.push_back({"friction_cone",
                 std::string("elliptic (option cone): Coulomb's circle, the same limit in every "
                             "direction of sliding; MuJoCo's friction is soft like its normal "
                             "force, so a body held by friction creeps at a speed that grows "
                             "with the force it holds")});
    add_friction_settings(world_, s);
    if (has_friction())
      s.push_back({"friction_model",
                   std::string("MuJoCo's convex soft contact: a contact's normal and friction "
                               "solved as one cost on the cone, friction rows at the velocity "
                               "level (reference acceleration -b v_t), so the solver may trade "
                               "the normal residual against the tangential one: a box sliding "
                               "fast is pushed off the ground and hops (the trajectory shows "
                               "it), and one held below the friction limit creeps at the speed "
                               "at which the velocity-dependent friction balances its load")});
    s.push_back({"restitution_rule",
                 std::string("MuJoCo has no restitution: the pair's restitution e sets the damping "
                             "ratio zeta of that spring and damper, which rebounds at e of its "
                             "approach speed, e = exp(-zeta pi / sqrt(1 - zeta^2))")});
    const double tau = std::max(kMujocoContactTime, 2.0 * dt_);
    s.push_back({"contact_time", tau});
    s.push_back({"contact_time_rule",
                 std::string("tau = max(0.02 s, 2 dt): MuJoCo's default time constant, never "
                             "below two steps, as its refsafe keeps its standard form")});
    s.push_back({"contact_damping_ratio_first",
                 mujoco_contact(pairs.front().restitution, dt_).damping_ratio});
    // MuJoCo 2.2.2 has one solref per pair, for its normal and its friction rows alike.
    if (std::any_of(pairs.begin(), pairs.end(), [](const ContactPair& p) {
          return engine_friction(p) > 0.0 && p.restitution >= 1.0;
        }))
      s.push_back({"friction_at_restitution_1",
                   std::string("none: a pair with friction and restitution 1 gets no friction. "
                               "MuJoCo 2.2.2 gives a pair one solref for its normal and its "
                               "friction rows; at e = 1 the damping b is 0, and a friction row "
                               "follows the reference acceleration -b v_t = 0, so it holds the "
                               "slide's acceleration at 0 instead of slowing it (2.2.2 has no "
                               "solreffriction)")});
  }
  /// Whether some pair has friction.
  bool has_friction() const {
    for (const ContactPair& pair : contact_pairs(world_))
      if (engine_friction(pair) > 0.0) return true;
    return false;
  }

  const World& world_;
  const EngineTables& engines_;  ///< the case's [engines.mujoco] table among the others
  std::string integrator_;       ///< MuJoCo's option integrator: what tells the backends apart
  double dt_;
  StepStart start_;  ///< impulses due and the force model's loads
  std::string xml_;
  mjModel* model_ = nullptr;
  mjData* data_ = nullptr;
  bool gyroscopic_;
  std::vector<int> qpos_, dof_;        ///< per body: its first qpos and dof, -1 when fixed
  std::vector<const Hinge*> hinges_;   ///< per body: its [[hinge]], or nullptr
  State state_{world_.bodies.size()};  ///< read before each step for the forces
  long steps_ = 0;                     ///< steps taken
  MujocoWarnings warnings_{world_};    ///< what MuJoCo did on its own, latched
};

/// Library and version as the linked MuJoCo says: {"mujoco", "2.3.3"}.
std::pair<std::string, std::string> mujoco_version() {
  const int v = mj_version();
  return {"mujoco", std::to_string(v / 100) + "." + std::to_string(v / 10 % 10) + "." +
                        std::to_string(v % 10)};
}

/// How the backend stepped by `integrator` starts a run: MuJoCo's error and warning handlers
/// set first (once per process).
DeclaredBackend::Start mujoco_start(const std::string& integrator) {
  return [integrator](const World& world, const BackendSettings& settings, double dt) {
    static std::once_flag handlers;
    std::call_once(handlers, [] {
      mju_user_error = mujoco_error;
      mju_user_warning = mujoco_warning;
    });
    return start_engine<MujocoSimulation>(integrator)(world, settings, dt);
  };
}

}  // namespace

}  // namespace bb

namespace {

/// The plugin's backends: MuJoCo's own integrators.
bb::Backend* mujoco_backend(int index) {
  static const std::vector<bb::VariantStart> starts = {
      {"mujoco", bb::mujoco_start("Euler")},
      {"mujoco/rk4", bb::mujoco_start("RK4")},
      {"mujoco/implicit", bb::mujoco_start("implicit")}};
  return bb::engine_backend(bb::mujoco_description(), bb::mujoco_version(), starts, index);
}

}  // namespace

BEACHBALL_PLUGIN_BACKENDS(mujoco_backend)
