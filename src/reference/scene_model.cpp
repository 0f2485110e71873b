#include "reference/scene_model.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>

#include "contact/contact_geometry.hpp"
#include "contact/impulse_response.hpp"
#include "model/motion.hpp"
#include "observe/event_watches.hpp"
#include "physics/cross_matrix.hpp"
#include "physics/hinge_motion.hpp"
#include "reference/gsl_reference.hpp"
#include "reference/scene_model_state.hpp"
#include "reference/sliding_modes.hpp"

namespace bb {

namespace {

using namespace state_view;

/// Euler's torque-free equations in the body's own frame, where the inertia is diagonal:
/// I dw/dt = -w x (I w). Integrated in the world frame instead (the same equations with
/// I = R I_body R^T), the spin of a box flipping about its middle axis came out 1e4 times
/// the tolerance off at 1e-10 (energy and momentum kept all the same): the orientation's
/// error fed the spin's at every step, and the flips amplified it.
Vector3d angular_acceleration(const Body& body, const Vector3d& body_omega) {
  const Vector3d principal = principal_inertia(body);
  if (principal.minCoeff() <= 0.0) return Vector3d::Zero();
  return (-body_omega.cross(principal.cwiseProduct(body_omega))).cwiseQuotient(principal);
}

/// d(angular_acceleration)/d(body_omega): I^-1 ([I w]x - [w]x I).
Eigen::Matrix3d angular_acceleration_by_spin(const Body& body, const Vector3d& body_omega) {
  const Vector3d principal = principal_inertia(body);
  if (principal.minCoeff() <= 0.0) return Eigen::Matrix3d::Zero();
  const Eigen::Matrix3d by_spin =
      skew(principal.cwiseProduct(body_omega)) - skew(body_omega) * principal.asDiagonal();
  return principal.cwiseInverse().asDiagonal() * by_spin;
}

}  // namespace

SceneModel::SceneModel(const World& scene, const BackendSettings& settings)
    : scene_(scene),
      settings_(settings),
      resting_(scene.bodies.size(), false),
      after_bounce_(scene.bodies.size(), false),
      forces_(scene),
      x_(scene.bodies.size()),
      v_(scene.bodies.size()),
      w_(scene.bodies.size()),
      q_(scene.bodies.size()),
      force_(scene.bodies.size()),
      torque_(scene.bodies.size()),
      accelerations_(scene.bodies.size()),
      applied_(scene.bodies.size()),
      slides_(scene.bodies.size()),
      mu_static_(scene.bodies.size(), 0.0),
      mu_kinetic_(scene.bodies.size(), 0.0),
      hinge_(scene.bodies.size(), nullptr),
      held_(scene.bodies.size(), false),
      hinge_held_(scene.bodies.size(), false),
      in_motion_(scene.bodies.size(), true) {
  trace_.bodies.resize(scene.bodies.size());
  // Every body's first motion begins at its start (a body at rest there ends it at once).
  for (std::size_t i = 0; i < scene.bodies.size(); ++i)
    trace_.bodies[i].motion_start = scene.bodies[i].position;
  for (const Hinge& h : scene.hinges) hinge_[h.body] = &h;
  for (const ContactPair& pair : contact_pairs(scene))
    sources_.push_back({Watch::Contact, -1, pair});
  // A body that may slide on a ground with friction: its coefficients and its stops.
  if (ground_rubs(scene))
    for (const ContactPair& pair : contact_pairs(scene))
      if (pair.ground()) {
        mu_static_[pair.a] = pair.friction_static, mu_kinetic_[pair.a] = pair.friction_kinetic;
        sources_.push_back({Watch::Stop, pair.a});
      }
  // Apexes are heights above the ground, watched while gravity pulls towards it.
  if (scene.ground && -scene.gravity.dot(scene.ground->normal) > 0.0)
    for (int i = 0; i < static_cast<int>(scene.bodies.size()); ++i)
      if (!scene.bodies[i].fixed) sources_.push_back({Watch::Apex, i});
  watch_observed(settings.observed());
  // A body that starts touching the ground, not moving along its normal, with gravity pressing it
  // down, starts at rest there (a gap of exactly zero is no crossing, so no event would).
  const std::vector<double> y = initial_state();
  for (const ContactPair& pair : contact_pairs(scene)) {
    if (!pair.ground()) continue;
    const Vector3d n = scene.ground->normal;
    const bool pressed = -scene.gravity.dot(n) > 0.0;
    if (hinge_[pair.a]) continue;  // a hinged body is held by its hinge, below
    if (pressed && std::abs(proximity(pair, y.data()).gap) <= kSimultaneousGap &&
        std::abs(velocity(y.data(), pair.a).dot(n)) <= kRestingNormalSpeed)
      resting_[pair.a] = true;
  }
  // A hinged body on the ground that its forces turn into it stays where it is.
  for (int i = 0; i < static_cast<int>(scene.bodies.size()); ++i)
    if (lands(i) && pressed_into_ground(i, y.data(), hinge_alpha(i, y.data())))
      hinge_held_[i] = true;
  // Resting on a ground with friction: stuck or sliding from the start.
  for (int i = 0; i < static_cast<int>(scene.bodies.size()); ++i)
    if (resting_[i]) settle(i, y.data(), 0.0);
}

void SceneModel::watch_observed(const std::vector<Observe>& observed) {
  // What the observes' kinds watch, each kind's event set up in EventWatches::add's switch.
  // A stop is an event of every body that slides on a rubbing ground, observed or not (the
  // constructor's); the stretch and the overlaps are peaks between events (PeakWatch).
  const EventWatches events = event_watches(scene_, observed);
  // Falls are timed exactly, as every backend's are from its steps.
  for (int body : events.falling) sources_.push_back({Watch::Fall, body});
  // Swings are timed exactly, as every backend's are from its steps: a hinged body's by its
  // spin about the axis, any other's by each component of its velocity.
  for (int body : events.swinging) {
    if (hinge_[body] != nullptr)
      sources_.push_back({Watch::HingeSwing, body});
    else
      for (int axis = 0; axis < 3; ++axis)
        for (const bool down : {false, true})
          sources_.push_back({Watch::Swing, body, {}, axis, down});
  }
  // A kind's crossings are located exactly, either way, as every backend's are from its steps.
  for (const CrossingWatch& w : events.crossings) {
    const Observe& o = *w.observe;
    trace_.crossings[o.name];
    for (const bool down : {false, true})
      sources_.push_back({Watch::Crossing, o.body, {}, -1, down, o, w.value});
  }
}

std::vector<double> SceneModel::initial_state() const {
  std::vector<double> y(dimension());
  const State start = ::bb::initial_state(scene_);
  for (std::size_t i = 0; i < start.size(); ++i) {
    const BodyState& s = start[i];
    double* p = y.data() + at(static_cast<int>(i));
    const double values[kPerBody - 3] = {
        s.position.x(), s.position.y(),    s.position.z(),    s.velocity.x(),    s.velocity.y(),
        s.velocity.z(), s.orientation.w(), s.orientation.x(), s.orientation.y(), s.orientation.z()};
    std::copy(std::begin(values), std::end(values), p);
    set_spin(y.data(), static_cast<int>(i), s.angular_velocity);
  }
  return y;
}

void SceneModel::read(const double* y, State& out) const {
  for (std::size_t i = 0; i < out.size(); ++i) out[i] = body_state(y, static_cast<int>(i));
}

void SceneModel::linear_accelerations(const double* y) {
  const int n = static_cast<int>(scene_.bodies.size());
  for (int i = 0; i < n; ++i) {
    x_[i] = position(y, i), v_[i] = velocity(y, i);
    // The world spin turns the body's by the quaternion just normalised (what spin() does).
    q_[i] = orientation(y, i).normalized(), w_[i] = q_[i] * Vector3d(body_spin(y, i));
  }
  forces_.evaluate({x_.data(), v_.data(), q_.data(), w_.data()}, force_.data(), torque_.data());
  for (int i = 0; i < n; ++i) {
    const Body& body = scene_.bodies[i];
    held_[i] = false;
    if (body.fixed) {
      accelerations_[i].setZero();
      continue;
    }
    Vector3d a = forces_.gravity() + force_[i] / body.mass;
    applied_[i] = a;
    // A body resting on the ground is held there: the ground takes any push into it, and
    // its friction holds the body (stuck) or acts against its sliding, mu_k N.
    const Vector3d n = resting_[i] ? scene_.ground->normal : Vector3d::UnitY();
    const double press = -a.dot(n);
    held_[i] = resting_[i] && press > 0.0;
    if (held_[i]) {
      a += press * n;
      const SlideDecision& slide = slides_[i];
      if (slide.mode == SlideMode::Stuck) a.setZero();
      if (slide.mode == SlideMode::Sliding) a -= mu_kinetic_[i] * press * slide.direction;
    }
    accelerations_[i] = a;
  }
}

Eigen::Matrix3d SceneModel::resting_projection(int i) const {
  Eigen::Matrix3d project = Eigen::Matrix3d::Identity();
  if (!held_[i]) return project;
  // Stuck, the body's acceleration is zero whatever the forces; sliding, the friction
  // mu_k N along a fixed direction depends on the state only through N, which nothing
  // the reference lets a sliding box feel (air, springs) changes.
  if (slides_[i].mode == SlideMode::Stuck) return Eigen::Matrix3d::Zero();
  project -= scene_.ground->normal * scene_.ground->normal.transpose();
  return project;
}

void SceneModel::derivatives(double, const double* y, double* dydt) {
  linear_accelerations(y);
  for (int i = 0; i < static_cast<int>(scene_.bodies.size()); ++i) {
    const Body& body = scene_.bodies[i];
    double* d = dydt + at(i);
    if (body.fixed || hinge_held_[i]) {
      std::fill(d, d + kPerBody, 0.0);
      continue;
    }
    const Vector3d v = velocity(y, i), own = body_spin(y, i);
    Vec{d} = v;
    Vec(d + 3) = accelerations_[i];
    // Orientation: dq/dt = 1/2 q (0, omega), with omega in the body frame.
    const Quaterniond q = orientation(y, i);
    const Quaterniond dq = q * Quaterniond(0.0, own.x(), own.y(), own.z());
    d[6] = 0.5 * dq.w(), d[7] = 0.5 * dq.x(), d[8] = 0.5 * dq.y(), d[9] = 0.5 * dq.z();
    Vec(d + 10) = angular_acceleration(body, own);
    // A torque (world frame) turns the body: I^-1 R^T T in its own frame.
    if (forces_.torques() && !torque_[i].isZero())
      Vec(d + 10) += (q_[i].conjugate() * torque_[i]).cwiseQuotient(principal_inertia(body));
    // On a hinge the body turns about the axis only: the forces at its centre act through
    // their torque about the axis, and the centre moves on a circle. (The Jacobian treats
    // it as free: only msbdf uses that, and a hinged scene here is never stiff.) The world
    // frame's angular acceleration is the body frame's turned: R^T alpha (the frame's own
    // turn adds omega x omega = 0).
    if (hinge_[i]) {
      const HingeAccelerations h = hinge_accelerations(body, q, position(y, i), w_[i],
                                                       body.mass * accelerations_[i], *hinge_[i]);
      Vec(d + 3) = h.linear;
      Vec(d + 10) = q_[i].conjugate() * h.angular;
    }
  }
}

void SceneModel::add_force_jacobian(const double* y, double* dfdy) {
  const auto n = static_cast<Eigen::Index>(dimension());
  Eigen::Map<Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>> j(dfdy, n, n);
  forces_.jacobian({x_.data(), v_.data(), q_.data(), w_.data()}, force_jacobian_);
  for (const JacobianBlock& block : force_jacobian_.blocks()) {
    const Body& moving = scene_.bodies[block.body];
    if (moving.fixed) continue;
    // dv/dt = g + F / m, projected onto the ground's plane while resting.
    const Eigen::Matrix3d project = resting_projection(block.body);
    const auto row = static_cast<Eigen::Index>(at(block.body) + 3);
    const auto col = static_cast<Eigen::Index>(at(block.by_body));
    if (block.wrt == Wrt::Position) j.block<3, 3>(row, col) += project * block.value / moving.mass;
    if (block.wrt == Wrt::Velocity)
      j.block<3, 3>(row, col + 3) += project * block.value / moving.mass;
    if (block.wrt != Wrt::Spin) continue;
    // The force sees the world's spin R(q) w, w the integrated spin in the body's frame.
    const Quaterniond q = orientation(y, block.by_body);
    const Vector3d own = body_spin(y, block.by_body);
    const Eigen::Matrix3d turn = q.normalized().toRotationMatrix();
    j.block<3, 3>(row, col + 10) += project * block.value * turn / moving.mass;
    // d(R(q) w)/dq by central differences (R of the normalised q).
    for (int c = 0; c < 4; ++c) {
      double up[4] = {q.w(), q.x(), q.y(), q.z()}, down[4] = {q.w(), q.x(), q.y(), q.z()};
      const double h = 1e-7 * std::max(1.0, std::abs(up[c]));
      up[c] += h, down[c] -= h;
      const Vector3d plus = Quaterniond(up[0], up[1], up[2], up[3]).normalized() * own;
      const Vector3d minus = Quaterniond(down[0], down[1], down[2], down[3]).normalized() * own;
      j.block<3, 1>(row, col + 6 + c) +=
          project * block.value * (plus - minus) / (2.0 * h * moving.mass);
    }
  }
}

void SceneModel::jacobian(double, const double* y, double* dfdy, double* dfdt) {
  const std::size_t n = dimension();
  std::fill(dfdy, dfdy + n * n, 0.0);
  std::fill(dfdt, dfdt + n, 0.0);
  linear_accelerations(y);
  Eigen::Map<Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>> j(
      dfdy, static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(n));
  for (int i = 0; i < static_cast<int>(scene_.bodies.size()); ++i) {
    const Body& body = scene_.bodies[i];
    if (body.fixed) continue;
    const auto o = static_cast<Eigen::Index>(at(i));
    const Vector3d own = body_spin(y, i);
    const Quaterniond q = orientation(y, i);
    // dx/dt = v.
    j.block<3, 3>(o, o + 3).setIdentity();
    // dq/dt = 1/2 q (0, w): w' = -w.q_v / 2, q_v' = (q_w w + q_v x w) / 2.
    const Vector3d qv(q.x(), q.y(), q.z());
    j.block<1, 3>(o + 6, o + 7) = -0.5 * own.transpose();
    j.block<1, 3>(o + 6, o + 10) = -0.5 * qv.transpose();
    j.block<3, 1>(o + 7, o + 6) = 0.5 * own;
    j.block<3, 3>(o + 7, o + 7) = -0.5 * skew(own);
    j.block<3, 3>(o + 7, o + 10) = 0.5 * (q.w() * Eigen::Matrix3d::Identity() + skew(qv));
    // Euler's equations in the body frame depend on the body's spin alone.
    j.block<3, 3>(o + 10, o + 10) = angular_acceleration_by_spin(body, own);
  }
  // dv/dt = g + F(x, v, omega) / m: the force model's derivatives.
  add_force_jacobian(y, dfdy);
}

}  // namespace bb
