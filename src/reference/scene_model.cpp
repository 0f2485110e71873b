#include "reference/scene_model.hpp"

#include <cmath>

#include "contact/contact_geometry.hpp"
#include "scene/air_forces.hpp"
#include "scene/motion.hpp"

namespace bb {

namespace {

using Eigen::Quaterniond;
using Eigen::Vector3d;
using ConstVec = Eigen::Map<const Vector3d>;
using Vec = Eigen::Map<Vector3d>;

Vector3d eigen(const Vec3& v) {
  return {v.x, v.y, v.z};
}
Vec3 plain(const Vector3d& v) {
  return {v.x(), v.y(), v.z()};
}

// Where each part of body i sits in the integrated state.
std::size_t at(int i) {
  return SceneModel::kPerBody * static_cast<std::size_t>(i);
}
ConstVec position(const double* y, int i) {
  return ConstVec(y + at(i));
}
ConstVec velocity(const double* y, int i) {
  return ConstVec(y + at(i) + 3);
}
Quaterniond orientation(const double* y, int i) {
  const double* q = y + at(i) + 6;
  return {q[0], q[1], q[2], q[3]};
}
ConstVec spin(const double* y, int i) {
  return ConstVec(y + at(i) + 10);
}

double radius(const Body& b) {
  return b.shape == Shape::Sphere ? b.radius : 0.0;
}
double inverse_mass(const Body& b) {
  return b.fixed ? 0.0 : 1.0 / b.mass;
}

/// Contact distance below which a second contact counts as simultaneous, metres.
constexpr double kSimultaneousGap = 1e-9;

}  // namespace

std::string SceneModel::beyond_exact_answer(const Scene& scene) {
  const bool touching = scene.ground || !scene.contacts.empty();
  for (const Body& b : scene.bodies)
    if (touching && !b.fixed && b.shape == Shape::Box)
      return "body '" + b.name +
             "' is a moving box that touches something: its contacts (edges, faces, tipping) "
             "have no event model in the reference";
  return "";
}

SceneModel::SceneModel(const Scene& scene)
    : scene_(scene),
      resting_(scene.bodies.size(), false),
      after_bounce_(scene.bodies.size(), false),
      force_(scene.bodies.size()) {
  const int n = static_cast<int>(scene.bodies.size());
  if (scene.ground)
    for (int i = 0; i < n; ++i)
      if (!scene.bodies[i].fixed)
        sources_.push_back({Source::Kind::Ground, i, -1, scene.ground->restitution});
  // Every pair a [[contact]] names once; the first entry naming a pair decides it.
  std::vector<std::vector<bool>> paired(n, std::vector<bool>(n, false));
  for (const Contact& c : scene.contacts)
    for (int a = 0; a < n; ++a)
      for (int b = a + 1; b < n; ++b) {
        const bool named =
            c.all_pairs || (c.body_a == a && c.body_b == b) || (c.body_a == b && c.body_b == a);
        if (!named || paired[a][b] || (scene.bodies[a].fixed && scene.bodies[b].fixed)) continue;
        paired[a][b] = true;
        // A fixed box is always the second shape.
        const bool swap = scene.bodies[a].shape == Shape::Box;
        sources_.push_back({Source::Kind::Pair, swap ? b : a, swap ? a : b, c.restitution});
      }
  if (scene.ground && -eigen(scene.gravity).dot(eigen(scene.ground->normal)) > 0.0)
    for (int i = 0; i < n; ++i)
      if (!scene.bodies[i].fixed) sources_.push_back({Source::Kind::Apex, i, -1, 0.0});
}

std::vector<double> SceneModel::initial_state() const {
  std::vector<double> y(dimension());
  const State start = ::bb::initial_state(scene_);
  for (std::size_t i = 0; i < start.size(); ++i) {
    const BodyState& s = start[i];
    double* p = y.data() + at(static_cast<int>(i));
    const double values[kPerBody] = {
        s.position.x,        s.position.y,    s.position.z,         s.velocity.x,
        s.velocity.y,        s.velocity.z,    s.orientation.w,      s.orientation.x,
        s.orientation.y,     s.orientation.z, s.angular_velocity.x, s.angular_velocity.y,
        s.angular_velocity.z};
    std::copy(values, values + kPerBody, p);
  }
  return y;
}

void SceneModel::read(const double* y, State& out) const {
  for (std::size_t i = 0; i < out.size(); ++i) {
    const int b = static_cast<int>(i);
    const Quaterniond q = orientation(y, b).normalized();
    out[i] = {plain(position(y, b)),
              plain(velocity(y, b)),
              {q.w(), q.x(), q.y(), q.z()},
              plain(spin(y, b))};
  }
}

void SceneModel::derivatives(double, const double* y, double* dydt) {
  for (int i = 0; i < static_cast<int>(scene_.bodies.size()); ++i) {
    const Body& body = scene_.bodies[i];
    double* d = dydt + at(i);
    if (body.fixed) {
      std::fill(d, d + kPerBody, 0.0);
      continue;
    }
    const Vector3d v = velocity(y, i), omega = spin(y, i);
    Vector3d a =
        eigen(scene_.gravity) + eigen(air_force(scene_, body, plain(v), plain(omega))) / body.mass;
    // A body resting on the ground is held there: the ground takes any push into it.
    if (resting_[i]) {
      const Vector3d n = eigen(scene_.ground->normal);
      if (a.dot(n) < 0.0) a -= a.dot(n) * n;
    }
    Vec{d} = v;
    Vec(d + 3) = a;
    // Orientation: dq/dt = 1/2 (0, omega) q, with omega in the world frame.
    const Quaterniond q = orientation(y, i);
    const Quaterniond dq = Quaterniond(0.0, omega.x(), omega.y(), omega.z()) * q;
    d[6] = 0.5 * dq.w(), d[7] = 0.5 * dq.x(), d[8] = 0.5 * dq.y(), d[9] = 0.5 * dq.z();
    // Euler's equations in the world frame, torque-free: I dw/dt = -w x (I w).
    const Vector3d principal = eigen(principal_inertia(body));
    if (principal.minCoeff() <= 0.0) {
      Vec(d + 10).setZero();
      continue;
    }
    const Eigen::Matrix3d r = q.normalized().toRotationMatrix();
    const Eigen::Matrix3d inertia = r * principal.asDiagonal() * r.transpose();
    Vec(d + 10) = inertia.ldlt().solve(-omega.cross(inertia * omega));
  }
}

double SceneModel::gap(const Source& s, const double* y) const {
  const Body& a = scene_.bodies[s.a];
  switch (s.kind) {
    case Source::Kind::Ground:
      return contact::sphere_plane(position(y, s.a), radius(a), eigen(scene_.ground->point),
                                   eigen(scene_.ground->normal))
          .gap;
    case Source::Kind::Pair: {
      const Body& b = scene_.bodies[s.b];
      if (b.shape == Shape::Box)
        return contact::sphere_box(position(y, s.a), radius(a), position(y, s.b),
                                   orientation(y, s.b), eigen(b.half_extents))
            .gap;
      return contact::sphere_sphere(position(y, s.a), radius(a), position(y, s.b), radius(b)).gap;
    }
    case Source::Kind::Apex:
      return 0.0;
  }
  return 0.0;
}

void SceneModel::events(double, const double* y, double* g) {
  for (std::size_t k = 0; k < sources_.size(); ++k) {
    const Source& s = sources_[k];
    if (s.kind == Source::Kind::Apex) {
      // The normal velocity falling through zero after a bounce is the apex.
      const bool watching = after_bounce_[s.a] && !resting_[s.a];
      g[k] = watching ? velocity(y, s.a).dot(eigen(scene_.ground->normal)) : 1.0;
    } else if (s.kind == Source::Kind::Ground && resting_[s.a]) {
      g[k] = 1.0;
    } else {
      g[k] = gap(s, y);
    }
  }
}

void SceneModel::check_simultaneous(const Source& s, const double* y, double t) const {
  for (const Source& other : sources_) {
    if (&other == &s || other.kind == Source::Kind::Apex) continue;
    const bool shares =
        other.a == s.a || other.a == s.b || other.b == s.a || (other.b >= 0 && other.b == s.b);
    if (!shares || (other.kind == Source::Kind::Ground && resting_[other.a])) continue;
    if (gap(other, y) <= kSimultaneousGap)
      throw BeyondExactAnswer(
          "at t = " + std::to_string(t) + " s body '" + scene_.bodies[s.a].name +
          "' touches two things at once: simultaneous contacts have no exact answer here");
  }
}

void SceneModel::resolve(const Source& s, double* y, double t) {
  const Body& a = scene_.bodies[s.a];
  const bool ground = s.kind == Source::Kind::Ground;
  const int b_index = ground ? -1 : s.b;
  contact::Proximity p;
  if (ground) {
    p = contact::sphere_plane(position(y, s.a), radius(a), eigen(scene_.ground->point),
                              eigen(scene_.ground->normal));
  } else if (scene_.bodies[s.b].shape == Shape::Box) {
    p = contact::sphere_box(position(y, s.a), radius(a), position(y, s.b), orientation(y, s.b),
                            eigen(scene_.bodies[s.b].half_extents));
  } else {
    p = contact::sphere_sphere(position(y, s.a), radius(a), position(y, s.b),
                               radius(scene_.bodies[s.b]));
  }
  const Vector3d relative =
      Vector3d(velocity(y, s.a)) - (ground ? Vector3d::Zero() : Vector3d(velocity(y, s.b)));
  const double closing = relative.dot(p.normal);
  // Touching while separating (a grazing root) needs no impulse.
  if (closing >= 0.0) return;
  check_simultaneous(s, y, t);
  const double wa = inverse_mass(a), wb = ground ? 0.0 : inverse_mass(scene_.bodies[s.b]);
  const double j = -(1.0 + s.restitution) * closing / (wa + wb);
  Vec(y + at(s.a) + 3) += j * wa * p.normal;
  if (!ground) Vec(y + at(s.b) + 3) -= j * wb * p.normal;
  log_.push_back({ContactRecord::Kind::Contact, s.a, b_index, t, 0.0});
  if (!ground) log_.push_back({ContactRecord::Kind::Contact, s.b, s.a, t, 0.0});
  after_bounce_[s.a] = true;
  if (!ground) after_bounce_[s.b] = true;
  for (int body : {s.a, b_index}) {
    if (body < 0 || !resting_[body] || !scene_.ground) continue;
    // An impulse may lift a resting body off the ground, but not press it in.
    const double up = velocity(y, body).dot(eigen(scene_.ground->normal));
    if (up < 0.0)
      throw BeyondExactAnswer("at t = " + std::to_string(t) + " s body '" +
                              scene_.bodies[body].name +
                              "' is pushed into the ground while resting on it");
    resting_[body] = up <= 0.0;
  }
  if (!ground || !scene_.ground) return;
  // Ever smaller bounces end: a rebound this short leaves the body resting on the ground.
  const Vector3d n = eigen(scene_.ground->normal);
  const double pull = -eigen(scene_.gravity).dot(n);
  const double rebound = velocity(y, s.a).dot(n);
  if (pull > 0.0 && 2.0 * rebound / pull < rest_flight_time()) {
    resting_[s.a] = true;
    after_bounce_[s.a] = false;
    Vec(y + at(s.a) + 3) -= rebound * n;
    Vec(y + at(s.a)) -= p.gap * n;
  }
}

void SceneModel::apply(std::size_t k, double t, double* y) {
  const Source& s = sources_[k];
  if (s.kind == Source::Kind::Apex) {
    const double height = (Vector3d(position(y, s.a)) - eigen(scene_.ground->point))
                              .dot(eigen(scene_.ground->normal));
    log_.push_back({ContactRecord::Kind::Apex, s.a, -1, t, height});
    after_bounce_[s.a] = false;
    return;
  }
  resolve(s, y, t);
}

}  // namespace bb
