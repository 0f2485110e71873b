// The Magnus force of a spinning ball (seed section 8): F = k (omega x (v - w)), w the wind.
#include "physics/cross_matrix.hpp"
#include "physics/force_term.hpp"
#include "physics/work_bounds.hpp"

namespace bb {

namespace {

class MagnusTerm : public ForceTerm {
 public:
  explicit MagnusTerm(const World& scene) : wind_(scene.air->wind), gravity_(scene.gravity.norm()) {
    for (std::size_t i = 0; i < scene.bodies.size(); ++i)
      if (scene.bodies[i].magnus != 0.0) {
        bodies_.push_back(static_cast<int>(i));
        k_.push_back(scene.bodies[i].magnus);
        mass_.push_back(scene.bodies[i].mass);
      }
  }
  bool empty() const { return bodies_.empty(); }

  void add(const BodyStates& s, Vec3* force, Vec3*) const override {
    for (std::size_t j = 0; j < bodies_.size(); ++j) {
      const int i = bodies_[j];
      force[i] += s.spin[i].cross(s.velocity[i] - wind_) * k_[j];
    }
  }

  /// Across the velocity relative to the air: no work in still air, at most what
  /// wind_work() bounds in a wind.
  double supply(const BodyStates&, double duration) const override {
    double work = 0.0;
    for (double m : mass_) work += wind_work(m, wind_.norm(), gravity_, duration);
    return work;
  }

  void add_jacobian(const BodyStates& s, ForceJacobian& out) const override {
    for (std::size_t j = 0; j < bodies_.size(); ++j) {
      const int i = bodies_[j];
      // d(k omega x u)/du = k skew(omega); d(k omega x u)/domega = -k skew(u).
      out.add(i, i, Wrt::Velocity, k_[j] * skew(s.spin[i]));
      out.add(i, i, Wrt::Spin, -(k_[j] * skew(s.velocity[i] - wind_)));
    }
  }

 private:
  Vec3 wind_;
  double gravity_;            ///< m/s^2
  std::vector<int> bodies_;   ///< bodies with a Magnus coefficient
  std::vector<double> k_;     ///< per body: kg
  std::vector<double> mass_;  ///< per body: kg
};

}  // namespace

std::unique_ptr<ForceTerm> make_magnus_term(const World& scene, const ForceOptions&) {
  if (!scene.air) return nullptr;
  auto term = std::make_unique<MagnusTerm>(scene);
  if (term->empty()) return nullptr;
  return term;
}

}  // namespace bb
