// The force model: the one place where the forces on the scene's bodies are summed. The
// course methods, the reference and every engine adapter evaluate the same terms
// (force_terms.hpp) at their own states; they differ only in how they step through time.
// Gravity is the uniform field every body falls in: an acceleration, added by whoever
// integrates (an engine through its world's gravity), never a term.
#pragma once

#include <memory>
#include <vector>

#include "physics/force_term.hpp"

namespace bb {

/// Forces (N, at the centre) and torques (N m, about the centre, world frame) per body.
struct Loads {
  std::vector<Vec3> force;
  std::vector<Vec3> torque;
};

class ForceModel {
 public:
  ForceModel(const World& scene, const ForceOptions& options = {});
  ForceModel(ForceModel&&) = default;
  ForceModel& operator=(ForceModel&&) = default;
  ~ForceModel();

  /// Whether any force acts (else callers need not read their state for it).
  bool empty() const { return terms_.empty(); }
  /// Whether any term gives a torque.
  bool torques() const { return torques_; }
  const Vec3& gravity() const { return gravity_; }

  /// Every body's force and torque at `s`, summed term by term in the registry's order;
  /// zero on fixed bodies. `force` and `torque` have one entry per body; nothing allocates.
  void evaluate(const BodyStates& s, Vec3* force, Vec3* torque) const;
  void evaluate(const BodyStates& s, Loads& out) const {
    evaluate(s, out.force.data(), out.torque.data());
  }
  /// The terms' derivatives at `s` (force_term.hpp), `out` cleared first.
  void jacobian(const BodyStates& s, ForceJacobian& out) const;
  /// The terms' potential energy at `s` (J), summed: force_term.hpp.
  double potential_energy(const BodyStates& s) const;
  /// Whether any term stores potential energy (else potential_energy() is 0 everywhere).
  bool stores_energy() const { return stores_energy_; }
  /// The most energy (J) the terms can put into the bodies' motion over a run of `duration`
  /// seconds from the case's start `start`, summed: force_term.hpp.
  double supply(const BodyStates& start, double duration) const;
  /// Loads sized for the scene, zero.
  Loads make_loads() const;

 private:
  std::vector<std::unique_ptr<ForceTerm>> terms_;
  std::vector<int> fixed_;  ///< bodies that never move: their loads are zero
  std::size_t bodies_ = 0;
  Vec3 gravity_;
  bool torques_ = false;
  bool stores_energy_ = false;
};

}  // namespace bb
