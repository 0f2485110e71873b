#include "course/spring_modes.hpp"

#include <Eigen/Eigenvalues>
#include <cmath>
#include <complex>

#include "course/integrators.hpp"
#include "model/motion.hpp"
#include "physics/state_forces.hpp"

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

/// The force model's derivative blocks with respect to `wrt` between moving bodies, at the
/// case's start: -dF/dx is the stiffness K, -dF/dv the damping C.
struct Coupling {
  int row = 0, column = 0;  ///< first degrees of freedom
  Eigen::Matrix3d value;    ///< -dF/d(wrt), mass-weighted: M^-1/2 (.) M^-1/2
};

std::vector<Coupling> couplings(const World& scene, const std::vector<int>& index,
                                const ForceJacobian& jacobian, Wrt wrt) {
  std::vector<Coupling> out;
  for (const JacobianBlock& b : jacobian.blocks()) {
    if (b.wrt != wrt || index[b.body] < 0 || index[b.by_body] < 0) continue;
    const double weight = 1.0 / std::sqrt(scene.bodies[b.body].mass * scene.bodies[b.by_body].mass);
    out.push_back({index[b.body], index[b.by_body], -weight * b.value});
  }
  return out;
}

/// y = A x for the symmetric part of the mass-weighted blocks A, without forming A.
void apply(const std::vector<Coupling>& blocks, int dims, const Eigen::VectorXd& x,
           Eigen::VectorXd& y) {
  y.setZero();
  for (const Coupling& c : blocks) {
    const Eigen::MatrixXd a = c.value.topLeftCorner(dims, dims);
    y.segment(c.row, dims) += 0.5 * a * x.segment(c.column, dims);
    y.segment(c.column, dims) += 0.5 * a.transpose() * x.segment(c.row, dims);
  }
}

/// The blocks as a dense n x n matrix (symmetric part).
Eigen::MatrixXd dense(const std::vector<Coupling>& blocks, int dims, int n) {
  Eigen::MatrixXd a = Eigen::MatrixXd::Zero(n, n);
  for (const Coupling& c : blocks) {
    const Eigen::MatrixXd v = c.value.topLeftCorner(dims, dims);
    a.block(c.row, c.column, dims, dims) += 0.5 * v;
    a.block(c.column, c.row, dims, dims) += 0.5 * v.transpose();
  }
  return a;
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
  if (n == 0) return std::nullopt;
  // The force model's own derivatives at the start: each term that has a stiffness gives it.
  StateForces forces(scene);
  ForceJacobian jacobian;
  forces.model().jacobian(forces.view(initial_state(scene)), jacobian);
  const std::vector<Coupling> stiffness = couplings(scene, index, jacobian, Wrt::Position);
  const std::vector<Coupling> damping = couplings(scene, index, jacobian, Wrt::Velocity);
  if (stiffness.empty()) return std::nullopt;
  StiffestMode mode;
  double lambda = 0.0;
  Eigen::VectorXd shape(n);  // the stiffest mode's shape, unit length
  if (n <= kDenseLimit) {
    const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> modes(dense(stiffness, scene.dims, n));
    Eigen::Index stiffest = 0;
    lambda = modes.eigenvalues().maxCoeff(&stiffest);
    shape = modes.eigenvectors().col(stiffest);
    mode.how = "the largest eigenvalue of M^-1 K at the start (" + std::to_string(n) +
               " degrees of freedom, K the force model's stiffness)";
  } else {
    // Power iteration from a checkerboard (the stiffest lattice modes alternate in sign);
    // the Rayleigh quotient approaches the largest eigenvalue from below.
    Eigen::VectorXd y(n);
    for (int i = 0; i < n; ++i)
      shape[i] = ((i / scene.dims) % 2 == 0 ? 1.0 : -1.0) + 1e-3 * (i % 7);
    shape.normalize();
    for (int iteration = 0; iteration < 500; ++iteration) {
      apply(stiffness, scene.dims, shape, y);
      lambda = shape.dot(y);
      shape = y.normalized();
    }
    mode.how = "500 power iterations on M^-1 K at the start (" + std::to_string(n) +
               " degrees of freedom, K the force model's stiffness; an estimate from below)";
  }
  if (!(lambda > 0.0)) return std::nullopt;
  mode.omega = std::sqrt(lambda);
  // The mode's own damping rate, v^T M^-1/2 C M^-1/2 v: exact where C = r K (every spring
  // with the same damping-to-stiffness ratio), the mode's share of C otherwise.
  Eigen::VectorXd damped(n);
  apply(damping, scene.dims, shape, damped);
  mode.damping_rate = std::max(shape.dot(damped), 0.0);
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
