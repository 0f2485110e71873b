// The reference solution: GSL's adaptive solvers (gsl_odeiv2) on the scene's own equations
// of motion, to a tight tolerance, contacts located as events. It starts with the explicit
// rk8pd and changes to the implicit msbdf, with the analytic Jacobian, where the scene is
// stiff (a light body in drag); each step() advances to the next multiple of dt exactly.
// Its self-check solves again with other methods (rkck, bsimp) and other step control.
#pragma once

#include "seam/backend.hpp"
#include "study/backend_names.hpp"

namespace bb {

/// Default absolute and relative tolerance of the reference solver.
inline constexpr double kReferenceTolerance = 1e-10;

/// The explicit method's steps are limited by stability, not accuracy, once the fastest
/// rate of the equations times the sample interval exceeds this: from there on the
/// reference solves with msbdf.
inline constexpr double kStiffRateTimesSample = 20.0;

/// The implicit method factors a dense Jacobian of 13 values per body; above this many
/// bodies a stiff scene is beyond the reference (the fallback of docs/design.md).
inline constexpr std::size_t kMaxImplicitBodies = 80;

/// Above this many bodies a scene with springs is beyond a tight reference in the time a
/// report allows (the fallback of docs/design.md).
inline constexpr std::size_t kMaxReferenceBodies = 400;
/// The most moving bodies that may touch each other for which the reference tries an
/// exact answer: beyond this a crowd (a pile, balls resting on balls) is what a scene makes,
/// and its simultaneous contacts have none.
inline constexpr std::size_t kMaxTouchingBodies = 8;

/// Which GSL methods solve the scene, and how their steps are controlled.
enum class ReferenceSolver {
  /// rk8pd, then msbdf where the scene is stiff; the error of each step is kept within
  /// abs + rel |y| (GSL's y control).
  Main,
  /// The self-check's: rkck (Cash-Karp's embedded 4(5) pair) where the main solve uses
  /// rk8pd, bsimp (implicit Bulirsch-Stoer) where it uses msbdf, and error kept within
  /// abs + rel (|y| + h |y'|) (GSL's standard control with a_dydt = 1). No stepper and no
  /// step control in common, so neither can hide an error of the other's. (GSL's msadams
  /// was tried and left: with its steps cut at the samples and events it strayed 1e4 times
  /// its tolerance from the closed form of a free top.)
  Check,
};

class ReferenceBackend : public Backend {
 public:
  /// `max_step_per_sample`: when above 0, no internal step is longer than this fraction of
  /// the sample interval (the self-check forces smaller steps than the reference takes).
  explicit ReferenceBackend(double tolerance = kReferenceTolerance,
                            double max_step_per_sample = 0.0,
                            ReferenceSolver solver = ReferenceSolver::Main)
      : tolerance_(tolerance), max_step_per_sample_(max_step_per_sample), solver_(solver) {}
  std::string name() const override { return kReferenceName; }
  FeatureSet supports() const override;
  std::pair<std::string, std::string> library_version() const override;
  std::unique_ptr<Simulation> start_run(const World& world, const BackendSettings& settings,
                                        double dt) const override;
  double tolerance() const { return tolerance_; }
  /// The self-check's solver: other methods and step control (ReferenceSolver::Check),
  /// 100 times tighter, with steps of at most an eighth of a sample.
  ReferenceBackend self_check() const {
    return ReferenceBackend(tolerance_ / 100.0, 0.125, ReferenceSolver::Check);
  }

 private:
  double tolerance_;
  double max_step_per_sample_;
  ReferenceSolver solver_;
};

}  // namespace bb
