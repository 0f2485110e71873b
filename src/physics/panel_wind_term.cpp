// The wind on a panel (seed section 8, the falling wall): a box with `wind_force` feels the
// part of it along the normal n of its broad face (the axis of its smallest half extent) as
// the box stands, (F.n) n, at its centre: F_w cos(phi) as the wall tips.
#include "physics/force_term.hpp"
#include "physics/work_bounds.hpp"

namespace bb {

namespace {

class PanelWindTerm : public ForceTerm {
 public:
  explicit PanelWindTerm(const World& scene) : gravity_(scene.gravity.norm()) {
    for (std::size_t i = 0; i < scene.bodies.size(); ++i) {
      const Body& b = scene.bodies[i];
      if (b.wind_force.isZero()) continue;
      Eigen::Index thin = 0;
      b.half_extents.minCoeff(&thin);
      bodies_.push_back(static_cast<int>(i));
      push_.push_back(b.wind_force);
      face_.push_back(Vec3::Unit(thin));
      mass_.push_back(b.mass);
    }
  }
  bool empty() const { return bodies_.empty(); }

  void add(const BodyStates& s, Vec3* force, Vec3*) const override {
    for (std::size_t j = 0; j < bodies_.size(); ++j) {
      const int i = bodies_[j];
      const Vec3 n = s.orientation[i] * face_[j];
      force[i] += n * push_[j].dot(n);
    }
  }

  /// At most the whole push, all the way: push_work().
  double supply(const BodyStates& start, double duration) const override {
    double work = 0.0;
    for (std::size_t j = 0; j < bodies_.size(); ++j)
      work += push_work(push_[j].norm(), mass_[j], start.velocity[bodies_[j]].norm(), gravity_,
                        duration);
    return work;
  }

 private:
  double gravity_;            ///< m/s^2
  std::vector<double> mass_;  ///< per box: kg
  std::vector<int> bodies_;   ///< boxes with a wind_force
  std::vector<Vec3> push_;    ///< per box: N, the push square on
  std::vector<Vec3> face_;    ///< per box: its broad face's normal in its own frame
};

}  // namespace

std::unique_ptr<ForceTerm> make_panel_wind_term(const World& scene, const ForceOptions&) {
  auto term = std::make_unique<PanelWindTerm>(scene);
  if (term->empty()) return nullptr;
  return term;
}

}  // namespace bb
