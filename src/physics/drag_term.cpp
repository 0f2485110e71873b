// Quadratic air drag (seed section 8, "the elephant falls faster"):
// F = -1/2 Cd A rho |v - w| (v - w), A = pi r^2, w the wind.
#include "physics/force_term.hpp"
#include "physics/work_bounds.hpp"

namespace bb {

namespace {

class DragTerm : public ForceTerm {
 public:
  explicit DragTerm(const World& scene) : air_(*scene.air), gravity_(scene.gravity.norm()) {
    for (std::size_t i = 0; i < scene.bodies.size(); ++i) {
      const Body& b = scene.bodies[i];
      if (b.drag_coefficient <= 0.0) continue;
      bodies_.push_back(static_cast<int>(i));
      k_.push_back(0.5 * b.drag_coefficient * frontal_area(b) * air_.density);
      mass_.push_back(b.mass);
    }
  }
  bool empty() const { return bodies_.empty(); }

  void add(const BodyStates& s, Vec3* force, Vec3*) const override {
    for (std::size_t j = 0; j < bodies_.size(); ++j) {
      const int i = bodies_[j];
      const Vec3 relative = s.velocity[i] - air_.wind;
      force[i] += relative * (-k_[j] * relative.norm());
    }
  }

  /// In still air drag only takes energy; a wind gives at most what wind_work() bounds.
  double supply(const BodyStates&, double duration) const override {
    double work = 0.0;
    for (double m : mass_) work += wind_work(m, air_.wind.norm(), gravity_, duration);
    return work;
  }

  void add_jacobian(const BodyStates& s, ForceJacobian& out) const override {
    for (std::size_t j = 0; j < bodies_.size(); ++j) {
      const int i = bodies_[j];
      // d(-k |u| u)/du = -k (|u| I + u u^T / |u|), which vanishes as u goes to zero.
      const Eigen::Vector3d u = s.velocity[i] - air_.wind;
      const double speed = u.norm();
      if (speed > 0.0)
        out.add(i, i, Wrt::Velocity,
                -(k_[j] * (speed * Eigen::Matrix3d::Identity() + u * u.transpose() / speed)));
    }
  }

 private:
  Air air_;
  double gravity_;            ///< m/s^2
  std::vector<int> bodies_;   ///< bodies with a drag coefficient
  std::vector<double> k_;     ///< per body: 1/2 Cd A rho, kg/m
  std::vector<double> mass_;  ///< per body: kg
};

}  // namespace

std::unique_ptr<ForceTerm> make_drag_term(const World& scene, const ForceOptions&) {
  if (!scene.air) return nullptr;
  auto term = std::make_unique<DragTerm>(scene);
  if (term->empty()) return nullptr;
  return term;
}

}  // namespace bb
