#include "physics/step_start.hpp"

namespace bb {

StepStart::StepStart(const World& scene, double dt, const ForceOptions& options)
    : scene_(&scene), dt_(dt), forces_(scene, options) {}

}  // namespace bb
