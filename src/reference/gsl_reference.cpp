#include "reference/gsl_reference.hpp"

#include <gsl/gsl_version.h>

#include <Eigen/Eigenvalues>
#include <memory>

#include "model/text.hpp"
#include "observe/event_watches.hpp"
#include "physics/force_model.hpp"
#include "physics/state_forces.hpp"
#include "reference/hybrid_integrator.hpp"
#include "reference/peak_watch.hpp"
#include "reference/scene_model.hpp"
#include "reference/sliding_modes.hpp"
#include "reference/wave_surface.hpp"

namespace bb {

namespace {

const char* kEvents = "contacts located as events to 1e-12 s";

/// The GSL methods and step control of a ReferenceSolver.
struct Methods {
  const gsl_odeiv2_step_type* smooth;  ///< explicit, while the scene is not stiff
  const gsl_odeiv2_step_type* stiff;   ///< implicit, with the Jacobian, once it is
  double derivative_weight;            ///< GSL's a_dydt
};

Methods methods(ReferenceSolver solver) {
  if (solver == ReferenceSolver::Check) return {gsl_odeiv2_step_rkck, gsl_odeiv2_step_bsimp, 1.0};
  return {gsl_odeiv2_step_rk8pd, gsl_odeiv2_step_msbdf, 0.0};
}

/// The fastest rate (1/s) at which the force model moves a body at state y, from its own
/// derivatives (force_term.hpp): per moving body, the stiffness bound sqrt(sum ||dF/dx|| / m)
/// on the angular frequency of the stiffest mode it takes part in (Gershgorin's circles on
/// M^-1 K), and the damping bound (||its own dF/dv|| + sum of the others') / m. A stiff
/// spring, or drag on a light body, makes it large; it is what limits an explicit method's step.
double fastest_rate(const World& scene, const SceneModel& model, StateForces& forces,
                    ForceJacobian& jacobian, const std::vector<double>& y) {
  State state(scene.bodies.size());
  model.read(y.data(), state);
  forces.model().jacobian(forces.view(state), jacobian);
  std::vector<double> stiffness(state.size(), 0.0), damping(state.size(), 0.0);
  std::vector<Eigen::Matrix3d> own(state.size(), Eigen::Matrix3d::Zero());
  for (const JacobianBlock& b : jacobian.blocks()) {
    if (b.wrt == Wrt::Position) stiffness[b.body] += b.value.norm();
    if (b.wrt != Wrt::Velocity) continue;
    if (b.body == b.by_body)
      own[b.body] += b.value;
    else
      damping[b.body] += b.value.norm();
  }
  double rate = 0.0;
  for (std::size_t i = 0; i < state.size(); ++i) {
    const Body& body = scene.bodies[i];
    if (body.fixed) continue;
    rate = std::max({rate, std::sqrt(stiffness[i] / body.mass),
                     (own[i].operatorNorm() + damping[i]) / body.mass});
  }
  return rate;
}

/// The scene as a hybrid system (scene_model.hpp), solved by the hybrid integrator. Impulses
/// due at a step's start are applied first, as every backend applies them.
class ReferenceSimulation : public Simulation {
 public:
  ReferenceSimulation(const World& scene, const BackendSettings& settings, double dt,
                      double tolerance, double max_step, ReferenceSolver solver)
      : scene_(scene),
        settings_(settings),
        dt_(dt),
        tolerance_(tolerance),
        max_step_(max_step),
        methods_(methods(solver)) {
    start_over(methods_.smooth);
    check_stiffness();
  }

  void step() override {
    const long target_step = steps_ + 1;
    try {
      advance_to_step(target_step);
    } catch (const BeyondExactAnswer&) {
      throw;
    } catch (const std::runtime_error& e) {
      if (implicit_) throw;
      // The explicit method failed: solve again from the start with the implicit one.
      switch_note_ = std::string(methods_.smooth->name) + " failed (" + e.what() +
                     "); solved from t = 0 by " + methods_.stiff->name;
      start_over(methods_.stiff);
      advance_to_step(target_step);
    }
    check_stiffness();
  }

  void read(State& out) const override { model_->read(integrator_->state().data(), out); }

  Settings settings() const override {
    Settings s = {{"method", method()},
                  {"tolerance", tolerance_},
                  {"event_tolerance", options(methods_.smooth).event_tolerance},
                  {"stiffness_rule", std::string(methods_.stiff->name) +
                                         " with the analytic Jacobian from where the fastest "
                                         "rate times the sample exceeds " +
                                         short_number(kStiffRateTimesSample)},
                  {"rest_rule", "a ground bounce whose flight would last less than " +
                                    short_number(model_->rest_flight_time()) +
                                    " s (1e-6 of a sample) leaves the body resting on the ground"}};
    if (max_step_ > 0.0) s.push_back({"max_step", max_step_});
    if (ground_rubs(scene_))
      s.push_back({"friction_rule",
                   std::string("Coulomb: a body resting on the ground sticks while the force "
                               "along it is at most mu_s N, else slides straight against "
                               "mu_k N; each stop located as an event, where mu_s decides "
                               "again")});
    return s;
  }
  std::optional<EventTrace> exact_events() const override {
    EventTrace trace = model_->trace();
    if (peaks_) peaks_->fill(trace);
    return trace;
  }
  std::optional<long> internal_steps() const override {
    return earlier_steps_ + integrator_->steps();
  }

 private:
  std::string method() const {
    const std::string control = methods_.derivative_weight > 0.0
                                    ? ", error kept within abs + rel (|y| + " +
                                          short_number(methods_.derivative_weight) + " h |y'|)"
                                    : "";
    const std::string steps =
        max_step_ > 0.0 ? ", steps of at most " + short_number(max_step_) + " s" : "";
    const std::string smooth = std::string("gsl_odeiv2 ") + methods_.smooth->name;
    if (!implicit_) return smooth + ", adaptive" + control + steps + ", with " + kEvents;
    return smooth + ", then " + methods_.stiff->name + " with the analytic Jacobian" + control +
           steps + ": " + switch_note_ + "; " + kEvents;
  }

  HybridOptions options(const gsl_odeiv2_step_type* method) const {
    HybridOptions o;
    o.method = method;
    o.absolute_tolerance = o.relative_tolerance = tolerance_;
    o.derivative_weight = methods_.derivative_weight;
    o.max_step = max_step_;
    o.watcher = peaks_.get();
    return o;
  }

  /// A fresh model and integrator at t = 0 with `method`.
  void start_over(const gsl_odeiv2_step_type* method) {
    implicit_ = method == methods_.stiff;
    earlier_steps_ += integrator_ ? integrator_->steps() : 0;
    integrator_.reset();
    model_ = std::make_unique<SceneModel>(scene_, settings_);
    // The largest stretch and overlap, found between the solver's steps.
    peaks_ = std::make_unique<PeakWatch>(scene_, event_watches(scene_, settings_.observed()),
                                         model_->initial_state());
    if (!peaks_->active()) peaks_.reset();
    integrator_ =
        std::make_unique<HybridIntegrator>(*model_, options(method), model_->initial_state());
    steps_ = 0;
    next_impulse_ = 0;
  }

  /// Advances to step n's end (n * dt, never an accumulated sum), impulses on the way.
  void advance_to_step(long n) {
    while (steps_ < n) {
      const double start = static_cast<double>(steps_) * dt_;
      const double target = static_cast<double>(++steps_) * dt_;
      while (next_impulse_ < scene_.impulses.size() &&
             scene_.impulses[next_impulse_].time < target) {
        const Impulse& impulse = scene_.impulses[next_impulse_++];
        // An impulse between samples is applied at its own time (a multiple of every dt).
        integrator_->advance_to(std::max(start, impulse.time));
        integrator_->change_state(
            [&](double* y) { model_->apply_impulse(impulse, integrator_->time(), y); });
      }
      integrator_->advance_to(target);
    }
  }

  /// Changes to the implicit method, from the current state on, where the explicit one's
  /// steps would be limited by stability rather than accuracy.
  void check_stiffness() {
    if (implicit_) return;
    const double rate =
        fastest_rate(scene_, *model_, rate_forces_, rate_jacobian_, integrator_->state());
    if (rate * settings_.sample <= kStiffRateTimesSample) return;
    const double t = integrator_->time();
    // The implicit methods factor a dense Jacobian of the whole state: beyond some size, too
    // slow to use.
    if (scene_.bodies.size() > kMaxImplicitBodies)
      throw BeyondExactAnswer("stiff (the fastest rate times the sample is " +
                              short_number(rate * settings_.sample) + ") with " +
                              std::to_string(scene_.bodies.size()) +
                              " bodies: the implicit solver's "
                              "dense Jacobian would take too long (it is used up to " +
                              std::to_string(kMaxImplicitBodies) + " bodies)");
    switch_note_ = "stiff from t = " + short_number(t) + " s, where the fastest rate is " +
                   short_number(rate) +
                   " /s (times the sample: " + short_number(rate * settings_.sample) + ")";
    implicit_ = true;
    earlier_steps_ += integrator_->steps();
    std::vector<double> y = integrator_->state();
    integrator_.reset();
    integrator_ =
        std::make_unique<HybridIntegrator>(*model_, options(methods_.stiff), std::move(y), t);
  }

  const World& scene_;
  StateForces rate_forces_{scene_};  ///< the whole force model, for its derivatives
  ForceJacobian rate_jacobian_;
  BackendSettings settings_;  ///< the sample interval and the observes
  double dt_;
  double tolerance_;
  double max_step_;  ///< seconds, 0: none
  Methods methods_;
  std::unique_ptr<SceneModel> model_;
  std::unique_ptr<PeakWatch> peaks_;  ///< null when no observable asks for a peak
  std::unique_ptr<HybridIntegrator> integrator_;
  bool implicit_ = false;
  std::string switch_note_;
  long steps_ = 0;
  long earlier_steps_ = 0;  ///< internal steps of integrators replaced since the start
  std::size_t next_impulse_ = 0;
};

}  // namespace

FeatureSet ReferenceBackend::supports() const {
  return force_stage_features() |
         FeatureSet{Feature::ThreeD,      Feature::Rotation,    Feature::GroundContact,
                    Feature::BodyContact, Feature::Restitution, Feature::Impulse,
                    Feature::Boxes,       Feature::Springs,     Feature::Friction,
                    Feature::Hinge,       Feature::Waves};
}

std::pair<std::string, std::string> ReferenceBackend::library_version() const {
  return {"gsl", GSL_VERSION};
}

std::unique_ptr<Simulation> ReferenceBackend::start_run(const World& scene,
                                                        const BackendSettings& settings,
                                                        double dt) const {
  // A kinematic surface: its truth is its formula.
  if (scene.waves) return start_wave_surface(scene, dt);
  if (const std::string why = SceneModel::beyond_exact_answer(scene); !why.empty())
    throw BeyondExactAnswer(why);
  return std::make_unique<ReferenceSimulation>(scene, settings, dt, tolerance_,
                                               max_step_per_sample_ * settings.sample, solver_);
}

}  // namespace bb
