// The course text's hand-written methods as a Backend: one integrator, one floor rule
// and one friction rule per variant.
#pragma once

#include "seam/backend.hpp"
#include "study/backend_names.hpp"

namespace bb {

class CourseBackend : public Backend {
 public:
  explicit CourseBackend(CourseVariant variant) : variant_(std::move(variant)) {}
  std::string name() const override { return variant_.name; }
  FeatureSet supports() const override;
  std::unique_ptr<Simulation> start_run(const World& world, const BackendSettings& settings,
                                        double dt) const override;

 private:
  CourseVariant variant_;
};

}  // namespace bb
