#include "course/course_step.hpp"

#include "course/plank_hit.hpp"
#include "seam/backend.hpp"

namespace bb::course {

ContactPhases::ContactPhases(const World& scene, const Phases& phases, double dt)
    : scene_(scene), phases_(phases), dt_(dt), pairs_(contact_pairs(scene)) {
  // The course moves a box as a point with an orientation: against the ground and a ball it
  // has an exact gap, against another box none here.
  for (const ContactPair& p : pairs_)
    if (!p.ground() && scene.bodies[p.a].shape == Shape::Box)
      throw UnsupportedScene("body '" + scene.bodies[p.a].name +
                             "' is a moving box that touches another box: the course's contact "
                             "rules take a moving box against the ground and balls only");
  found_.reserve(pairs_.size());
}

void ContactPhases::detect(const std::vector<Vec3>& x, const std::vector<Quat>& q) {
  found_.clear();
  for (std::size_t k = 0; k < pairs_.size(); ++k) {
    const ContactPair& p = pairs_[k];
    const int b = p.ground() ? p.a : p.b;
    const contact::Proximity near = contact::measure(scene_, p, x[p.a], x[b], q[b]);
    if (near.gap < 0.0) found_.push_back({k, near});
  }
}

void ContactPhases::hit(const ContactPair& pair, const contact::Proximity& p,
                        const std::vector<Vec3>& x, std::vector<Vec3>& v,
                        const std::vector<Quat>& q, std::vector<Vec3>& w) const {
  const Body &ball = scene_.bodies[pair.a], &box = scene_.bodies[pair.b];
  contact::HitBody a = contact::hit_body(ball, x[pair.a], q[pair.a], v[pair.a], w[pair.a]);
  contact::HitBody b = contact::hit_body(box, x[pair.b], q[pair.b], v[pair.b], w[pair.b]);
  // Only while the two surface points approach, as the blend between balls.
  const Vec3 arm_b = p.point - x[pair.b];
  const Vec3 relative = a.velocity - b.velocity - b.spin.cross(arm_b);
  if (relative.dot(p.normal) >= 0.0) return;
  if (phases_.hit == HitRule::SeedPlank)
    seed_plank_hit(a, b, p.point, p.normal);
  else
    contact::impulse_hit(a, b, p.point, p.normal, pair.restitution);
  v[pair.a] = a.velocity, w[pair.a] = a.spin;
  v[pair.b] = b.velocity, w[pair.b] = b.spin;
}

void ContactPhases::resolve(std::vector<Vec3>& x, std::vector<Vec3>& v, const std::vector<Quat>& q,
                            std::vector<Vec3>& w) {
  for (const FoundContact& c : found_) {
    const ContactPair& p = pairs_[c.pair];
    const Body& a = scene_.bodies[p.a];
    if (p.ground() || scene_.bodies[p.b].fixed) {
      // Seed section 3: the ground rule, for the floor and for walls alike.
      resolve_fixed(phases_.ground, c.proximity, p.restitution, x[p.a], v[p.a]);
      // Seed section 5: a ball that hits a surface rolls along it (SetRotation).
      if (phases_.spin != SpinRule::Free && a.shape == Shape::Sphere)
        w[p.a] = contact_spin(v[p.a], c.proximity.normal, a.radius);
      continue;
    }
    // Seed section 5: a ball against a moving box, the plank.
    if (scene_.bodies[p.b].shape == Shape::Box) {
      hit(p, c.proximity, x, v, q, w);
      continue;
    }
    // Seed section 4: the blend along the line of centres, while the bodies approach.
    if ((v[p.a] - v[p.b]).dot(c.proximity.normal) >= 0.0) continue;
    Eigen::Vector3d va = v[p.a], vb = v[p.b];
    blend_collision(a.mass, scene_.bodies[p.b].mass, p.restitution, c.proximity.normal, va, vb);
    v[p.a] = va, v[p.b] = vb;
    // Seed section 5, "Many beachballs": two touching balls share their spins.
    if (phases_.spin == SpinRule::Shared) share_spins(w[p.a], w[p.b], dt_);
  }
}

}  // namespace bb::course
