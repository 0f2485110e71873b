// Springs of seed section 7 as a force term: Hooke's law with a damper along each spring
// (model/spring_forces.hpp holds the loop, inlined here).
#include "model/spring_forces.hpp"
#include "physics/cross_matrix.hpp"
#include "physics/force_term.hpp"

namespace bb {

namespace {

class SpringTerm : public ForceTerm {
 public:
  explicit SpringTerm(const World& scene) : springs_(spring_network(scene)) {}

  void add(const BodyStates& s, Vec3* force, Vec3*) const override {
    add_spring_forces(springs_, s.position, s.velocity, force);
  }

  bool stores_energy() const override { return true; }
  double potential_energy(const BodyStates& s) const override {
    return spring_energy(springs_, s.position);
  }

  /// A spring gives back at most what it stores at the start (its damper only takes).
  double supply(const BodyStates& start, double) const override {
    return spring_energy(springs_, start.position);
  }

  void add_jacobian(const BodyStates& s, ForceJacobian& out) const override {
    for (std::size_t k = 0; k < springs_.size(); ++k) {
      const int a = springs_.a[k], b = springs_.b[k];
      const Eigen::Vector3d d = s.position[b] - s.position[a];
      const double length = d.norm();
      if (length == 0.0) continue;
      const Eigen::Vector3d u = d / length, dv = s.velocity[b] - s.velocity[a];
      const double stiffness = springs_.stiffness[k], damping = springs_.damping[k];
      const double tension = stiffness * (length - springs_.rest_length[k]) + damping * dv.dot(u);
      // F_a = tension u with d = x_b - x_a: dF_a/dd = k u u^T + c u dv^T P / l + tension P / l,
      // P = I - u u^T the projection across the spring; dF_a/dv_b = c u u^T; F_b = -F_a.
      const Eigen::Matrix3d across = Eigen::Matrix3d::Identity() - u * u.transpose();
      const Eigen::Matrix3d by_d = stiffness * u * u.transpose() +
                                   (damping / length) * u * dv.transpose() * across +
                                   (tension / length) * across;
      const Eigen::Matrix3d by_dv = damping * u * u.transpose();
      for (const auto& [body, sign] : {std::pair{a, 1.0}, std::pair{b, -1.0}}) {
        out.add(body, b, Wrt::Position, sign * by_d);
        out.add(body, a, Wrt::Position, -sign * by_d);
        out.add(body, b, Wrt::Velocity, sign * by_dv);
        out.add(body, a, Wrt::Velocity, -sign * by_dv);
      }
    }
  }

 private:
  SpringNetwork springs_;
};

}  // namespace

std::unique_ptr<ForceTerm> make_spring_term(const World& scene, const ForceOptions& options) {
  if (scene.springs.empty() || !options.springs) return nullptr;
  return std::make_unique<SpringTerm>(scene);
}

}  // namespace bb
