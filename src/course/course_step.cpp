#include "course/course_step.hpp"

#include "scene/backend.hpp"

namespace bb::course {

ContactPhases::ContactPhases(const Scene& scene, GroundRule rule)
    : scene_(scene), rule_(rule), pairs_(contact_pairs(scene)) {
  // The course moves a box as a point with an orientation: against the ground it has an
  // exact gap, against another body none here.
  for (const ContactPair& p : pairs_)
    if (!p.ground() && scene.bodies[p.a].shape == Shape::Box)
      throw UnsupportedScene("body '" + scene.bodies[p.a].name +
                             "' is a moving box that touches another body: the course's contact "
                             "rules take a moving box against the ground only");
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

void ContactPhases::resolve(std::vector<Vec3>& x, std::vector<Vec3>& v) {
  for (const FoundContact& c : found_) {
    const ContactPair& p = pairs_[c.pair];
    const bool against_fixed = p.ground() || scene_.bodies[p.b].fixed;
    Eigen::Vector3d xa = x[p.a], va = v[p.a];
    if (against_fixed) {
      // Seed section 3: the ground rule, for the floor and for walls alike.
      resolve_fixed(rule_, c.proximity, p.restitution, xa, va);
    } else {
      // Seed section 4: the blend along the line of centres, while the bodies approach.
      Eigen::Vector3d vb = v[p.b];
      if ((va - vb).dot(c.proximity.normal) >= 0.0) continue;
      blend_collision(scene_.bodies[p.a].mass, scene_.bodies[p.b].mass, p.restitution,
                      c.proximity.normal, va, vb);
      v[p.b] = vb;
    }
    x[p.a] = xa;
    v[p.a] = va;
  }
}

}  // namespace bb::course
