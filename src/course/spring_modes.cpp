#include "course/spring_modes.hpp"

#include <Eigen/Eigenvalues>
#include <cmath>
#include <complex>

#include "course/integrators.hpp"

namespace bb {

namespace {

/// Above this many degrees of freedom the dense eigensolver is too slow: power iteration.
constexpr int kDenseLimit = 1200;

/// Each moving body's first degree of freedom, or -1 for a fixed body.
std::vector<int> dof_index(const World& scene, int& count) {
  std::vector<int> index(scene.bodies.size(), -1);
  count = 0;
  for (std::size_t i = 0; i < scene.bodies.size(); ++i)
    if (!scene.bodies[i].fixed) index[i] = count, count += scene.dims;
  return index;
}

/// y = M^-1/2 K M^-1/2 x without forming K: a sweep over the springs.
void apply_stiffness(const World& scene, const std::vector<int>& index, const Eigen::VectorXd& x,
                     Eigen::VectorXd& y) {
  y.setZero();
  const int d = scene.dims;
  for (const Spring& s : scene.springs) {
    const Vec3 delta = scene.bodies[s.body_b].position - scene.bodies[s.body_a].position;
    if (delta.norm() == 0.0) continue;
    const Eigen::VectorXd u = (delta / delta.norm()).head(d);
    const int a = index[s.body_a], b = index[s.body_b];
    const double wa = a < 0 ? 0.0 : 1.0 / std::sqrt(scene.bodies[s.body_a].mass);
    const double wb = b < 0 ? 0.0 : 1.0 / std::sqrt(scene.bodies[s.body_b].mass);
    // The spring stretches by u.(x_b - x_a); its force k u u^T acts on both ends.
    double stretch = 0.0;
    if (a >= 0) stretch -= wa * u.dot(x.segment(a, d));
    if (b >= 0) stretch += wb * u.dot(x.segment(b, d));
    if (a >= 0) y.segment(a, d) -= s.stiffness * stretch * wa * u;
    if (b >= 0) y.segment(b, d) += s.stiffness * stretch * wb * u;
  }
}

/// Spectral radius of the integrator's step matrix on the scalar mode, from two steps.
double spectral_radius(course::StepFn step, double omega, double gamma, double h) {
  const course::AccelerationFn a = [&](const std::vector<Vec3>& x, const std::vector<Vec3>& v,
                                       std::vector<Vec3>& out) {
    out[0] = -omega * omega * x[0] - gamma * v[0];
  };
  course::Workspace w;
  w.resize(1);
  course::PointState from_x{{Vec3(1, 0, 0)}, {Vec3::Zero()}};
  course::PointState from_v{{Vec3::Zero()}, {Vec3(1, 0, 0)}};
  step(from_x, h, a, w);
  step(from_v, h, a, w);
  Eigen::Matrix2d m;
  m << from_x.x[0].x(), from_v.x[0].x(), from_x.v[0].x(), from_v.v[0].x();
  return m.eigenvalues().cwiseAbs().maxCoeff();
}

}  // namespace

std::optional<StiffestMode> stiffest_mode(const World& scene) {
  int n = 0;
  const std::vector<int> index = dof_index(scene, n);
  bool any = false;
  for (const Spring& s : scene.springs) any = any || index[s.body_a] >= 0 || index[s.body_b] >= 0;
  if (!any || n == 0) return std::nullopt;
  StiffestMode mode;
  double lambda = 0.0;
  if (n <= kDenseLimit) {
    // Dense: K column by column from the spring sweep, then every eigenvalue.
    Eigen::MatrixXd k(n, n);
    Eigen::VectorXd e = Eigen::VectorXd::Zero(n), column(n);
    for (int c = 0; c < n; ++c) {
      e[c] = 1.0;
      apply_stiffness(scene, index, e, column);
      k.col(c) = column;
      e[c] = 0.0;
    }
    lambda = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(k, Eigen::EigenvaluesOnly)
                 .eigenvalues()
                 .maxCoeff();
    mode.how = "the largest eigenvalue of M^-1 K at the start (" + std::to_string(n) +
               " degrees of freedom, axial spring stiffness)";
  } else {
    // Power iteration from a checkerboard (the stiffest lattice modes alternate in sign);
    // the Rayleigh quotient approaches the largest eigenvalue from below.
    Eigen::VectorXd x(n), y(n);
    for (int i = 0; i < n; ++i) x[i] = ((i / scene.dims) % 2 == 0 ? 1.0 : -1.0) + 1e-3 * (i % 7);
    x.normalize();
    for (int iteration = 0; iteration < 500; ++iteration) {
      apply_stiffness(scene, index, x, y);
      lambda = x.dot(y);
      x = y.normalized();
    }
    mode.how = "500 power iterations on M^-1 K at the start (" + std::to_string(n) +
               " degrees of freedom; an estimate from below)";
  }
  mode.omega = std::sqrt(std::max(lambda, 0.0));
  // Modal damping where C = r K: every spring with the same damping-to-stiffness ratio.
  const double ratio = scene.springs.front().damping / scene.springs.front().stiffness;
  for (const Spring& s : scene.springs)
    if (std::abs(s.damping / s.stiffness - ratio) > 1e-12 * ratio) mode.damping_known = false;
  if (mode.damping_known) mode.damping_rate = ratio * lambda;
  return mode;
}

double linear_stability_limit(const std::string& integrator, double omega, double gamma) {
  const course::StepFn step = course::integrator(integrator);
  const auto stable = [&](double h) {
    return spectral_radius(step, omega, gamma, h) <= 1.0 + 1e-12;
  };
  // Bisection in log h between a small step (where explicit Euler's excess, h^2 omega^2 / 2,
  // is still far above rounding) and one far past every method's limit.
  double lo = 1e-3 / omega, hi = 10.0 / omega;
  if (!stable(lo)) return 0.0;
  if (stable(hi)) return hi;
  while (hi / lo > 1.0 + 1e-9) {
    const double mid = std::sqrt(lo * hi);
    (stable(mid) ? lo : hi) = mid;
  }
  return lo;
}

}  // namespace bb
