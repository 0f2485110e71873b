#include "reference/gsl_reference.hpp"

#include <gsl/gsl_version.h>

#include "reference/hybrid_integrator.hpp"
#include "reference/scene_model.hpp"

namespace bb {

namespace {

/// The scene as a hybrid system (scene_model.hpp), solved by the hybrid integrator: smooth
/// flight by rk8pd, every contact located as an event and resolved by its law. Each step()
/// advances to the next multiple of dt exactly; impulses due at a step's start are applied
/// first, as every backend applies them.
class ReferenceSimulation : public Simulation {
 public:
  ReferenceSimulation(const Scene& scene, double dt, double tolerance)
      : scene_(scene),
        dt_(dt),
        tolerance_(tolerance),
        model_(scene),
        integrator_(model_, options(tolerance), model_.initial_state()) {}

  void step() override {
    const double start = static_cast<double>(steps_) * dt_;
    // Targets are n * dt, never an accumulated sum.
    const double target = static_cast<double>(++steps_) * dt_;
    while (next_impulse_ < scene_.impulses.size() && scene_.impulses[next_impulse_].time < target) {
      const Impulse& impulse = scene_.impulses[next_impulse_++];
      // An impulse between samples is applied at its own time (a multiple of every dt).
      integrator_.advance_to(std::max(start, impulse.time));
      integrator_.change_state(
          [&](double* y) { model_.apply_impulse(impulse, integrator_.time(), y); });
    }
    integrator_.advance_to(target);
  }

  void read(State& out) const override { model_.read(integrator_.state().data(), out); }

  Settings settings() const override {
    return {{"method", ReferenceBackend::method()},
            {"tolerance", tolerance_},
            {"event_tolerance", options(tolerance_).event_tolerance},
            {"rest_rule", "a ground bounce whose flight would last less than " +
                              std::to_string(model_.rest_flight_time()) +
                              " s (1e-6 of a sample) leaves the body resting on the ground"}};
  }
  std::optional<EventTrace> exact_events() const override { return model_.trace(); }
  std::optional<long> internal_steps() const override { return integrator_.steps(); }

 private:
  static HybridOptions options(double tolerance) {
    HybridOptions o;
    o.absolute_tolerance = o.relative_tolerance = tolerance;
    return o;
  }

  const Scene& scene_;
  double dt_;
  double tolerance_;
  SceneModel model_;
  HybridIntegrator integrator_;
  long steps_ = 0;
  std::size_t next_impulse_ = 0;
};

}  // namespace

FeatureSet ReferenceBackend::supports() const {
  return {Feature::ThreeD,      Feature::Gravity,  Feature::Drag,          Feature::Magnus,
          Feature::Wind,        Feature::Rotation, Feature::GroundContact, Feature::BodyContact,
          Feature::Restitution, Feature::Impulse,  Feature::Boxes};
}

std::pair<std::string, std::string> ReferenceBackend::library_version() const {
  return {"gsl", GSL_VERSION};
}

std::unique_ptr<Simulation> ReferenceBackend::start(const Scene& scene, double dt) const {
  if (const std::string why = SceneModel::beyond_exact_answer(scene); !why.empty())
    throw BeyondExactAnswer(why);
  return std::make_unique<ReferenceSimulation>(scene, dt, tolerance_);
}

}  // namespace bb
