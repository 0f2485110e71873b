#include "course/friction_phase.hpp"

#include <algorithm>

#include "contact/contact_pairs.hpp"
#include "seam/backend.hpp"

namespace bb::course {

FrictionPhase::FrictionPhase(const World& scene, FrictionRule rule, double dt)
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
  resolved_.assign(bodies_.size(), 0);
  entry_.assign(scene.bodies.size(), -1);
  for (std::size_t k = 0; k < bodies_.size(); ++k) entry_[bodies_[k]] = static_cast<int>(k);
  before_.assign(bodies_.size(), Vec3::Zero());
  pull_ = std::max(0.0, -scene.gravity.dot(normal_));
}

void FrictionPhase::begin(const std::vector<Vec3>& x, const std::vector<Quat>& q,
                          const std::vector<Vec3>& v) {
  for (std::size_t k = 0; k < bodies_.size(); ++k) {
    const int i = bodies_[k];
    const double gap = contact::measure(scene_, pairs_[k], x[i], x[i], q[i]).gap;
    // In contact before and not leaving: its flight from here under gravity alone would
    // end within four steps (mirror keeps a block at rest hopping up to g dt^2 * 2 high, a
    // flight of four steps).
    const double hop = 4.0 * dt_;
    const bool stays = gap + v[i].dot(normal_) * hop - 0.5 * pull_ * hop * hop <= kTouching;
    touching_[k] = gap <= kTouching || ((touching_[k] || resolved_[k]) && stays);
    resolved_[k] = 0;
    before_[k] = v[i];
  }
}

bool FrictionPhase::stops_slides() const {
  if (rule_ != FrictionRule::Clamp) return false;
  for (char t : touching_)
    if (t) return true;
  return false;
}

void FrictionPhase::stop_slides(const std::vector<Vec3>& a, std::vector<Vec3>& v) {
  for (std::size_t k = 0; k < bodies_.size(); ++k) {
    if (!touching_[k]) continue;
    const int i = bodies_[k];
    if (stops_within(coulomb_[k], normal_, v[i], a[i], dt_)) {
      v[i] -= tangential(v[i], normal_);
      before_[k] = v[i];
    }
  }
}

void FrictionPhase::resolved(int body) {
  if (entry_[body] >= 0) resolved_[entry_[body]] = 1;
}

void FrictionPhase::apply(const std::vector<Vec3>& v, std::vector<Vec3>& a) const {
  for (std::size_t k = 0; k < bodies_.size(); ++k) {
    if (!touching_[k]) continue;
    const int i = bodies_[k];
    a[i] = with_friction(rule_, coulomb_[k], normal_, v[i], a[i], dt_);
  }
}

void FrictionPhase::end(std::vector<Vec3>& v) {
  for (std::size_t k = 0; k < bodies_.size(); ++k)
    if (touching_[k]) clamp_reversal(rule_, normal_, before_[k], v[bodies_[k]]);
}

}  // namespace bb::course
