// A boat's sail in the wind (seed section 9, "Boat 1"). The apparent wind is the wind less
// the boat's velocity, v_a = v_w - v_s. The sail is planar and friction-free, so the wind
// pushes it only along its normal n, by the drag formula on its area (the flat plate's
// quadratic law, physics/flat_plate.hpp, which the wind panel shares):
//   F = 1/2 rho_air C_s A (v_a . n) |v_a . n| n.
// The sail's line makes `angle` with the heading, its boom out to leeward (the side the
// apparent wind blows towards), and n is the normal the wind blows along, so the sail is
// never pushed upwind. Heel (optional): the sideways part of that force tilts the boat by
// phi = F_across / heel_stiffness (at most 90 degrees), and the area the wind sees falls to
// A cos(phi).
#include <algorithm>
#include <cmath>
#include <numbers>

#include "physics/boat_frame.hpp"
#include "physics/flat_plate.hpp"
#include "physics/force_term.hpp"

namespace bb {

namespace {

class SailTerm : public ForceTerm {
 public:
  explicit SailTerm(const World& scene) : wind_(scene.air->wind) {
    for (std::size_t i = 0; i < scene.bodies.size(); ++i)
      if (scene.bodies[i].sail) {
        bodies_.push_back(static_cast<int>(i));
        sails_.push_back(*scene.bodies[i].sail);
        half_rho_c_a_.push_back(0.5 * scene.air->density * sails_.back().coefficient *
                                sails_.back().area);
        angle_.push_back(sails_.back().angle * std::numbers::pi / 180.0);
        mass_.push_back(scene.bodies[i].mass);
      }
  }
  bool empty() const { return bodies_.empty(); }

  void add(const BodyStates& s, Vec3* force, Vec3*) const override {
    for (std::size_t j = 0; j < bodies_.size(); ++j) {
      const int i = bodies_[j];
      force[i] += push(j, boat_frame(s.orientation[i]), s.velocity[i]);
    }
  }

  void add_jacobian(const BodyStates& s, ForceJacobian& out) const override {
    for (std::size_t j = 0; j < bodies_.size(); ++j) {
      const int i = bodies_[j];
      const BoatFrame frame = boat_frame(s.orientation[i]);
      Eigen::Matrix3d d = Eigen::Matrix3d::Zero();
      if (sails_[j].heel_stiffness == 0.0) {
        // d/dv of K (v_a . n)^2 n with v_a = w - v and n fixed on a side: -2 K (v_a . n) n n^T.
        const Vec3 apparent = wind_ - s.velocity[i];
        d = flat_plate_push_by_velocity(PlateLaw::Quadratic, half_rho_c_a_[j], apparent,
                                        normal(j, frame, apparent));
      } else {
        // With heel the area depends on the force too: central differences in the velocity.
        const double h = 1e-6 * std::max(1.0, s.velocity[i].norm());
        for (int k = 0; k < 3; ++k) {
          Vec3 up = s.velocity[i], down = s.velocity[i];
          up[k] += h, down[k] -= h;
          d.col(k) = (push(j, frame, up) - push(j, frame, down)) / (2.0 * h);
        }
      }
      out.add(i, i, Wrt::Velocity, d);
    }
  }

  /// A sail drives its boat at most ten times the wind's speed (an ice boat reaches about
  /// five): the kinetic energy of that speed.
  double supply(const BodyStates&, double) const override {
    const double fastest = kFastestSailing * wind_.norm();
    double work = 0.0;
    for (double m : mass_) work += 0.5 * m * fastest * fastest;
    return work;
  }

 private:
  /// The fastest a sail drives a boat, in wind speeds.
  static constexpr double kFastestSailing = 10.0;

  /// The sail's normal that the apparent wind blows along.
  Vec3 normal(std::size_t j, const BoatFrame& frame, const Vec3& apparent) const {
    // The boom swings to leeward: the sail's line turns from the heading towards the side
    // the wind comes from (starboard when the wind blows to port).
    const double side = apparent.dot(frame.across) > 0.0 ? -1.0 : 1.0;
    const double a = angle_[j];
    const Vec3 line = std::cos(a) * frame.ahead + side * std::sin(a) * frame.across;
    Vec3 n(-line.y(), line.x(), 0.0);
    if (apparent.dot(n) < 0.0) n = -n;
    return n;
  }

  /// The sail's force on a boat heading along `frame` at `velocity`.
  Vec3 push(std::size_t j, const BoatFrame& frame, const Vec3& velocity) const {
    const Vec3 apparent = wind_ - velocity;
    Vec3 f = flat_plate_push(PlateLaw::Quadratic, half_rho_c_a_[j], apparent,
                             normal(j, frame, apparent));
    if (sails_[j].heel_stiffness > 0.0) {
      const double heel =
          std::min(std::abs(f.dot(frame.across)) / sails_[j].heel_stiffness, std::numbers::pi / 2);
      f *= std::cos(heel);
    }
    return f;
  }

  Vec3 wind_;
  std::vector<int> bodies_;           ///< bodies with a sail
  std::vector<Sail> sails_;           ///< per body
  std::vector<double> half_rho_c_a_;  ///< per body: 1/2 rho_air C_s A, kg/m
  std::vector<double> angle_;         ///< per body: the sail's angle from the heading, rad
  std::vector<double> mass_;          ///< per body: kg
};

}  // namespace

std::unique_ptr<ForceTerm> make_sail_term(const World& scene, const ForceOptions&) {
  if (!scene.air) return nullptr;
  auto term = std::make_unique<SailTerm>(scene);
  if (term->empty()) return nullptr;
  return term;
}

}  // namespace bb
