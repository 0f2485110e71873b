// The reference solution: GSL's adaptive rk8pd (gsl_odeiv2) on the scene's own equations
// of motion, to a tight tolerance. Each step() advances to the next multiple of dt exactly.
#pragma once

#include "scene/backend.hpp"

namespace bb {

/// Default absolute and relative tolerance of the reference solver.
inline constexpr double kReferenceTolerance = 1e-10;

class ReferenceBackend : public Backend {
 public:
  explicit ReferenceBackend(double tolerance = kReferenceTolerance) : tolerance_(tolerance) {}
  std::string name() const override { return "reference"; }
  FeatureSet supports() const override;
  std::pair<std::string, std::string> library_version() const override;
  std::unique_ptr<Simulation> start(const Scene& scene, double dt) const override;
  double tolerance() const { return tolerance_; }
  /// How the method is named in results.
  static std::string method() {
    return "gsl_odeiv2 rk8pd, adaptive, with contacts located as events to 1e-12 s";
  }

 private:
  double tolerance_;
};

}  // namespace bb
