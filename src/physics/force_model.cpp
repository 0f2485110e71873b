#include "physics/force_model.hpp"

#include "physics/force_terms.hpp"

namespace bb {

ForceModel::ForceModel(const World& scene, const ForceOptions& options)
    : bodies_(scene.bodies.size()), gravity_(scene.gravity) {
  for (const ForceTermEntry& entry : force_terms())
    if (std::unique_ptr<ForceTerm> term = entry.make(scene, options)) {
      torques_ = torques_ || term->torques();
      stores_energy_ = stores_energy_ || term->stores_energy();
      terms_.push_back(std::move(term));
    }
  for (std::size_t i = 0; i < scene.bodies.size(); ++i)
    if (scene.bodies[i].fixed) fixed_.push_back(static_cast<int>(i));
}

ForceModel::~ForceModel() = default;

void ForceModel::evaluate(const BodyStates& s, Vec3* force, Vec3* torque) const {
  for (std::size_t i = 0; i < bodies_; ++i) force[i].setZero(), torque[i].setZero();
  for (const auto& term : terms_) term->add(s, force, torque);
  // A fixed body is an anchor: what acts on it moves nothing.
  for (int i : fixed_) force[i].setZero(), torque[i].setZero();
}

void ForceModel::jacobian(const BodyStates& s, ForceJacobian& out) const {
  out.clear();
  for (const auto& term : terms_) term->add_jacobian(s, out);
}

double ForceModel::potential_energy(const BodyStates& s) const {
  double energy = 0.0;
  for (const auto& term : terms_) energy += term->potential_energy(s);
  return energy;
}

double ForceModel::supply(const BodyStates& start, double duration) const {
  double energy = 0.0;
  for (const auto& term : terms_) energy += term->supply(start, duration);
  return energy;
}

Loads ForceModel::make_loads() const {
  return {std::vector<Vec3>(bodies_, Vec3::Zero()), std::vector<Vec3>(bodies_, Vec3::Zero())};
}

}  // namespace bb
