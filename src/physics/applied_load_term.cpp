// A constant force and torque on a body ([[body]] `force`, `torque`): a thruster, a hand
// pushing steadily, a motor. World frame; the force acts at the centre.
#include "physics/force_term.hpp"
#include "physics/work_bounds.hpp"

namespace bb {

namespace {

class AppliedLoadTerm : public ForceTerm {
 public:
  explicit AppliedLoadTerm(const World& scene) : gravity_(scene.gravity.norm()) {
    for (std::size_t i = 0; i < scene.bodies.size(); ++i) {
      const Body& b = scene.bodies[i];
      if (b.force.isZero() && b.torque.isZero()) continue;
      bodies_.push_back(static_cast<int>(i));
      force_.push_back(b.force);
      torque_.push_back(b.torque);
      mass_.push_back(b.mass);
      moment_.push_back(principal_inertia(b).minCoeff());
      torques_ = torques_ || !b.torque.isZero();
    }
  }
  bool empty() const { return bodies_.empty(); }
  bool torques() const override { return torques_; }

  void add(const BodyStates&, Vec3* force, Vec3* torque) const override {
    for (std::size_t j = 0; j < bodies_.size(); ++j) {
      force[bodies_[j]] += force_[j];
      torque[bodies_[j]] += torque_[j];
    }
  }

  /// The push's and the turn's work over the whole run: push_work() and turn_work().
  double supply(const BodyStates& start, double duration) const override {
    double work = 0.0;
    for (std::size_t j = 0; j < bodies_.size(); ++j) {
      const int i = bodies_[j];
      work += push_work(force_[j].norm(), mass_[j], start.velocity[i].norm(), gravity_, duration);
      if (moment_[j] > 0.0)
        work += turn_work(torque_[j].norm(), moment_[j], start.spin[i].norm(), duration);
    }
    return work;
  }

 private:
  double gravity_;           ///< m/s^2
  std::vector<int> bodies_;  ///< bodies with a force or a torque
  std::vector<Vec3> force_, torque_;
  std::vector<double> mass_, moment_;  ///< per body: kg, and its smallest moment (kg m^2)
  bool torques_ = false;
};

}  // namespace

std::unique_ptr<ForceTerm> make_applied_load_term(const World& scene, const ForceOptions&) {
  auto term = std::make_unique<AppliedLoadTerm>(scene);
  if (term->empty()) return nullptr;
  return term;
}

}  // namespace bb
