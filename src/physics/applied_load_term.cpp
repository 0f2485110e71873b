// A constant force and torque on a body ([[body]] `force`, `torque`): a thruster, a hand
// pushing steadily, a motor. World frame; the force acts at the centre.
#include "physics/force_term.hpp"

namespace bb {

namespace {

class AppliedLoadTerm : public ForceTerm {
 public:
  explicit AppliedLoadTerm(const World& scene) {
    for (std::size_t i = 0; i < scene.bodies.size(); ++i) {
      const Body& b = scene.bodies[i];
      if (b.force.isZero() && b.torque.isZero()) continue;
      bodies_.push_back(static_cast<int>(i));
      force_.push_back(b.force);
      torque_.push_back(b.torque);
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

 private:
  std::vector<int> bodies_;  ///< bodies with a force or a torque
  std::vector<Vec3> force_, torque_;
  bool torques_ = false;
};

}  // namespace

std::unique_ptr<ForceTerm> make_applied_load_term(const World& scene, const ForceOptions&) {
  auto term = std::make_unique<AppliedLoadTerm>(scene);
  if (term->empty()) return nullptr;
  return term;
}

}  // namespace bb
