#include "course/friction_phase.hpp"

#include "contact/contact_pairs.hpp"
#include "scene/backend.hpp"

namespace bb::course {

FrictionPhase::FrictionPhase(const Scene& scene, FrictionRule rule, double dt)
    : scene_(scene), rule_(rule), dt_(dt) {
  for (const Contact& c : scene.contacts)
    if (!c.ground && (c.friction_static > 0.0 || c.friction_kinetic > 0.0))
      throw UnsupportedScene("the [[contact]] at line " + std::to_string(c.line) +
                             " has friction: the course's friction rules (seed section 6) act "
                             "between a body and the ground only");
  if (!scene.ground) return;
  normal_ = scene.ground->normal;
  for (const ContactPair& p : contact_pairs(scene))
    if (p.ground() && (p.friction_static > 0.0 || p.friction_kinetic > 0.0)) {
      pairs_.push_back(p), bodies_.push_back(p.a);
      coulomb_.push_back({p.friction_static, p.friction_kinetic});
    }
  touching_.assign(bodies_.size(), 0);
  before_.assign(bodies_.size(), Vec3::Zero());
}

void FrictionPhase::begin(const std::vector<Vec3>& x, const std::vector<Quat>& q,
                          const std::vector<Vec3>& v) {
  for (std::size_t k = 0; k < bodies_.size(); ++k) {
    const int i = bodies_[k];
    touching_[k] = contact::measure(scene_, pairs_[k], x[i], x[i], q[i]).gap <= kTouching;
    before_[k] = v[i];
  }
}

void FrictionPhase::apply(const std::vector<Vec3>& v, std::vector<Vec3>& a) const {
  for (std::size_t k = 0; k < bodies_.size(); ++k) {
    if (!touching_[k]) continue;
    const int i = bodies_[k];
    a[i] = with_friction(rule_, coulomb_[k], normal_, v[i], a[i], dt_);
  }
}

void FrictionPhase::end(std::vector<Vec3>& v) const {
  for (std::size_t k = 0; k < bodies_.size(); ++k)
    if (touching_[k]) clamp_reversal(rule_, normal_, before_[k], v[bodies_[k]]);
}

}  // namespace bb::course
