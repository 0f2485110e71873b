#include "reference/gsl_reference.hpp"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_odeiv2.h>
#include <gsl/gsl_version.h>

#include <stdexcept>
#include <string>

#include "scene/motion.hpp"

namespace bb {

namespace {

/// y holds, per body, x (3 values) then v (3 values); spins stay constant (torque-free spheres).
class ReferenceSimulation : public Simulation {
 public:
  ReferenceSimulation(const Scene& scene, double dt, double tolerance)
      : scene_(scene), dt_(dt), tolerance_(tolerance), start_(initial_state(scene)) {
    const std::size_t n = start_.size();
    x_.resize(n);
    v_.resize(n);
    omega_.resize(n);
    a_.resize(n);
    y_.resize(6 * n);
    for (std::size_t i = 0; i < n; ++i) {
      omega_[i] = start_[i].angular_velocity;
      store(i, start_[i].position, start_[i].velocity);
    }
    system_ = {&ReferenceSimulation::derivatives, nullptr, 6 * n, this};
    driver_ = gsl_odeiv2_driver_alloc_y_new(&system_, gsl_odeiv2_step_rk8pd, std::min(dt, 1e-3),
                                            tolerance, tolerance);
    if (driver_ == nullptr) throw std::runtime_error("GSL could not allocate the ODE driver");
  }
  ~ReferenceSimulation() override { gsl_odeiv2_driver_free(driver_); }
  ReferenceSimulation(const ReferenceSimulation&) = delete;
  ReferenceSimulation& operator=(const ReferenceSimulation&) = delete;

  void step() override {
    // Targets are n * dt, never an accumulated sum.
    const double target = static_cast<double>(++steps_) * dt_;
    const int status = gsl_odeiv2_driver_apply(driver_, &t_, target, y_.data());
    // The driver counts steps per call; the evolver keeps the total.
    internal_steps_ = static_cast<long>(driver_->e->count);
    if (status != GSL_SUCCESS)
      throw std::runtime_error(std::string("GSL rk8pd failed at t = ") + std::to_string(t_) +
                               " s: " + gsl_strerror(status));
  }

  void read(State& out) const override {
    for (std::size_t i = 0; i < out.size(); ++i) {
      const double* p = &y_[6 * i];
      // A constant spin turns the start orientation by |omega| t about omega.
      const Quat turn = quat_from_rotation_vector(omega_[i], t_);
      out[i] = {{p[0], p[1], p[2]}, {p[3], p[4], p[5]}, turn * start_[i].orientation, omega_[i]};
    }
  }

  Settings settings() const override {
    return {{"method", ReferenceBackend::method()}, {"tolerance", tolerance_}};
  }
  std::optional<long> internal_steps() const override { return internal_steps_; }

 private:
  void store(std::size_t i, const Vec3& x, const Vec3& v) {
    double* p = &y_[6 * i];
    p[0] = x.x, p[1] = x.y, p[2] = x.z, p[3] = v.x, p[4] = v.y, p[5] = v.z;
  }

  static int derivatives(double, const double y[], double dydt[], void* self_ptr) {
    auto& self = *static_cast<ReferenceSimulation*>(self_ptr);
    const std::size_t n = self.x_.size();
    for (std::size_t i = 0; i < n; ++i) {
      self.x_[i] = {y[6 * i], y[6 * i + 1], y[6 * i + 2]};
      self.v_[i] = {y[6 * i + 3], y[6 * i + 4], y[6 * i + 5]};
    }
    accelerations(self.scene_, self.x_, self.v_, self.omega_, self.a_);
    for (std::size_t i = 0; i < n; ++i) {
      double* d = &dydt[6 * i];
      d[0] = self.v_[i].x, d[1] = self.v_[i].y, d[2] = self.v_[i].z;
      d[3] = self.a_[i].x, d[4] = self.a_[i].y, d[5] = self.a_[i].z;
    }
    return GSL_SUCCESS;
  }

  const Scene& scene_;
  double dt_;
  double tolerance_;
  State start_;
  std::vector<Vec3> x_, v_, omega_, a_;
  std::vector<double> y_;
  gsl_odeiv2_system system_{};
  gsl_odeiv2_driver* driver_ = nullptr;
  double t_ = 0.0;
  long steps_ = 0;
  long internal_steps_ = 0;
};

}  // namespace

FeatureSet ReferenceBackend::supports() const {
  return {Feature::ThreeD, Feature::Gravity, Feature::Drag,
          Feature::Magnus, Feature::Wind,    Feature::Rotation};
}

std::pair<std::string, std::string> ReferenceBackend::library_version() const {
  return {"gsl", GSL_VERSION};
}

std::unique_ptr<Simulation> ReferenceBackend::start(const Scene& scene, double dt) const {
  // GSL's default handler aborts the process; failures are reported through return codes.
  gsl_set_error_handler_off();
  return std::make_unique<ReferenceSimulation>(scene, dt, tolerance_);
}

}  // namespace bb
