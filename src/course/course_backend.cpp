#include "course/course_backend.hpp"

#include "course/course_step.hpp"
#include "course/integrators.hpp"
#include "scene/motion.hpp"

namespace bb {

namespace {

class CourseSimulation : public Simulation {
 public:
  CourseSimulation(const Scene& scene, double dt, const CourseVariant& variant)
      : scene_(scene),
        dt_(dt),
        phases_{course::integrator(variant.integrator), course::ground_rule(variant.ground)},
        contacts_(scene, phases_.ground) {
    const State start = initial_state(scene);
    for (const BodyState& b : start) {
      points_.x.push_back(b.position);
      points_.v.push_back(b.velocity);
      orientation_.push_back(b.orientation);
      omega_.push_back(b.angular_velocity);
      spins_ = spins_ || norm(b.angular_velocity) > 0.0;
    }
    work_.resize(start.size());
    settings_ = {{"integrator", variant.integrator}};
    if (!contacts_.empty()) settings_.push_back({"ground_rule", variant.ground});
    acceleration_ = [this](const std::vector<Vec3>& x, const std::vector<Vec3>& v,
                           std::vector<Vec3>& a) { accelerations(scene_, x, v, omega_, a); };
  }

  void step() override {
    // Forces and integrate: the integrator evaluates the forces at each of its stages.
    phases_.integrate(points_, dt_, acceleration_, work_);
    // Detect, then resolve: the ground rule against fixed surfaces, the blend between bodies.
    if (!contacts_.empty()) {
      contacts_.detect(points_.x);
      contacts_.resolve(points_.x, points_.v);
    }
    // Seed section 5, kinematic rotation: each frame the orientation is multiplied on the
    // left by the rotation the spin makes in one step (exact for a torque-free sphere).
    if (spins_)
      for (std::size_t i = 0; i < omega_.size(); ++i)
        orientation_[i] = normalized(quat_from_rotation_vector(omega_[i], dt_) * orientation_[i]);
  }

  void read(State& out) const override {
    for (std::size_t i = 0; i < out.size(); ++i)
      out[i] = {points_.x[i], points_.v[i], orientation_[i], omega_[i]};
  }

  Settings settings() const override { return settings_; }

 private:
  const Scene& scene_;
  double dt_;
  course::Phases phases_;
  course::ContactPhases contacts_;
  course::PointState points_;
  course::Workspace work_;
  course::AccelerationFn acceleration_;
  std::vector<Quat> orientation_;
  std::vector<Vec3> omega_;
  bool spins_ = false;
  Settings settings_;
};

}  // namespace

FeatureSet CourseBackend::supports() const {
  return {Feature::ThreeD,        Feature::Gravity,     Feature::Drag,
          Feature::Magnus,        Feature::Wind,        Feature::Rotation,
          Feature::GroundContact, Feature::BodyContact, Feature::Restitution};
}

std::unique_ptr<Simulation> CourseBackend::start(const Scene& scene, double dt) const {
  return std::make_unique<CourseSimulation>(scene, dt, variant_);
}

}  // namespace bb
