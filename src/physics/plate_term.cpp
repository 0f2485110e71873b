// The wind panel (seed section 8, "Wind"): a box with a [body.plate] is pushed at its
// centre along the normal n of its broad face (the axis of its smallest half extent, turned
// with the box) by the wind relative to it, by the text's linear law or the sail's
// quadratic one (physics/flat_plate.hpp). At the centre: no torque, so nothing turns the
// panel; its spin is whatever it was given.
#include "physics/flat_plate.hpp"
#include "physics/force_term.hpp"
#include "physics/work_bounds.hpp"

namespace bb {

namespace {

class PlateTerm : public ForceTerm {
 public:
  explicit PlateTerm(const World& scene) : wind_(scene.air->wind), gravity_(scene.gravity.norm()) {
    for (std::size_t i = 0; i < scene.bodies.size(); ++i) {
      const Body& b = scene.bodies[i];
      if (!b.plate) continue;
      Eigen::Index thin = 0;
      b.half_extents.minCoeff(&thin);
      bodies_.push_back(static_cast<int>(i));
      law_.push_back(b.plate->law);
      factor_.push_back(b.plate->law == PlateLaw::Course
                            ? b.plate->k * b.plate->area
                            : 0.5 * scene.air->density * b.plate->coefficient * b.plate->area);
      face_.push_back(Vec3::Unit(thin));
      mass_.push_back(b.mass);
    }
  }
  bool empty() const { return bodies_.empty(); }

  void add(const BodyStates& s, Vec3* force, Vec3*) const override {
    for (std::size_t j = 0; j < bodies_.size(); ++j) {
      const int i = bodies_[j];
      force[i] +=
          flat_plate_push(law_[j], factor_[j], wind_ - s.velocity[i], s.orientation[i] * face_[j]);
    }
  }

  void add_jacobian(const BodyStates& s, ForceJacobian& out) const override {
    for (std::size_t j = 0; j < bodies_.size(); ++j) {
      const int i = bodies_[j];
      out.add(i, i, Wrt::Velocity,
              flat_plate_push_by_velocity(law_[j], factor_[j], wind_ - s.velocity[i],
                                          s.orientation[i] * face_[j]));
    }
  }

  /// Pushed by the wind relative to it: at most what wind_work() bounds.
  double supply(const BodyStates&, double duration) const override {
    double work = 0.0;
    for (double m : mass_) work += wind_work(m, wind_.norm(), gravity_, duration);
    return work;
  }

 private:
  Vec3 wind_;
  double gravity_;              ///< m/s^2
  std::vector<double> mass_;    ///< per body: kg
  std::vector<int> bodies_;     ///< bodies with a plate
  std::vector<PlateLaw> law_;   ///< per body
  std::vector<double> factor_;  ///< per body: k a (N s/m) or 1/2 rho C a (kg/m)
  std::vector<Vec3> face_;      ///< per body: its broad face's normal in its own frame
};

}  // namespace

std::unique_ptr<ForceTerm> make_plate_term(const World& scene, const ForceOptions&) {
  if (!scene.air) return nullptr;
  auto term = std::make_unique<PlateTerm>(scene);
  if (term->empty()) return nullptr;
  return term;
}

}  // namespace bb
