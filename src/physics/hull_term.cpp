// A boat's hull in still water (seed section 9): the boat's velocity split along its heading
// and across it, each part with its own quadratic drag, -1/2 rho_water (C A) u |u|: low ahead
// (a different area astern) and high across, the keel. With `no_drift` the drag across is
// infinite: the keel takes every force across the heading (this term, summed last, cancels
// what the others push sideways), so a boat that starts along its heading goes on along it.
#include "physics/boat_frame.hpp"
#include "physics/force_term.hpp"

namespace bb {

namespace {

class HullTerm : public ForceTerm {
 public:
  explicit HullTerm(const World& scene) {
    const double half_rho = 0.5 * scene.water->density;
    for (std::size_t i = 0; i < scene.bodies.size(); ++i)
      if (const std::optional<Hull>& h = scene.bodies[i].hull) {
        bodies_.push_back(static_cast<int>(i));
        hulls_.push_back(
            {half_rho * h->forward, half_rho * h->backward, half_rho * h->sideways, h->no_drift});
      }
  }
  bool empty() const { return bodies_.empty(); }

  void add(const BodyStates& s, Vec3* force, Vec3*) const override {
    for (std::size_t j = 0; j < bodies_.size(); ++j) {
      const int i = bodies_[j];
      const BoatFrame frame = boat_frame(s.orientation[i]);
      const Drag& k = hulls_[j];
      const double ahead = s.velocity[i].dot(frame.ahead);
      force[i] -= (ahead >= 0.0 ? k.forward : k.backward) * ahead * std::abs(ahead) * frame.ahead;
      if (k.no_drift) {
        force[i] -= force[i].dot(frame.across) * frame.across;
      } else {
        const double across = s.velocity[i].dot(frame.across);
        force[i] -= k.sideways * across * std::abs(across) * frame.across;
      }
    }
  }

  void add_jacobian(const BodyStates& s, ForceJacobian& out) const override {
    for (std::size_t j = 0; j < bodies_.size(); ++j) {
      const int i = bodies_[j];
      const BoatFrame frame = boat_frame(s.orientation[i]);
      const Drag& k = hulls_[j];
      const Eigen::Vector3d h = frame.ahead, p = frame.across;
      const double ahead = s.velocity[i].dot(h);
      // d/dv of -k u |u| h with u = v . h: -2 k |u| h h^T.
      Eigen::Matrix3d own =
          -2.0 * (ahead >= 0.0 ? k.forward : k.backward) * std::abs(ahead) * h * h.transpose();
      if (k.no_drift) {
        // The keel cancels the sideways part of every block the terms before it gave.
        const Eigen::Matrix3d across = p * p.transpose();
        const std::size_t before = out.blocks().size();
        for (std::size_t b = 0; b < before; ++b) {
          const JacobianBlock block = out.blocks()[b];
          if (block.body == i) out.add(i, block.by_body, block.wrt, -across * block.value);
        }
        own -= across * own;
      } else {
        own -= 2.0 * k.sideways * std::abs(s.velocity[i].dot(p)) * p * p.transpose();
      }
      out.add(i, i, Wrt::Velocity, own);
    }
  }

 private:
  /// 1/2 rho_water C A per direction, kg/m.
  struct Drag {
    double forward, backward, sideways;
    bool no_drift;
  };
  std::vector<int> bodies_;  ///< bodies with a hull
  std::vector<Drag> hulls_;  ///< per body
};

}  // namespace

std::unique_ptr<ForceTerm> make_hull_term(const World& scene, const ForceOptions&) {
  if (!scene.water) return nullptr;
  auto term = std::make_unique<HullTerm>(scene);
  if (term->empty()) return nullptr;
  return term;
}

}  // namespace bb
