#include "run/engine_interventions.hpp"

#include "model/text.hpp"

namespace bb {

std::optional<EngineIntervention> intervention_of(const std::vector<EngineIntervention>& all,
                                                  EngineIntervention::Kind kind) {
  for (const EngineIntervention& i : all)
    if (i.kind == kind) return i;
  return std::nullopt;
}

double intervention_time(const EngineIntervention& intervention, double dt) {
  return static_cast<double>(intervention.step) * dt;
}

std::string intervention_reason(const EngineIntervention& intervention, double dt) {
  const bool reset = intervention.kind == EngineIntervention::Kind::Reset;
  return intervention.what + (reset ? " at t = " : " from t = ") +
         significant_digits(intervention_time(intervention, dt), 6) + " s" +
         (intervention.cause.empty() ? "" : ": " + intervention.cause);
}

std::optional<StabilityTrial> intervened_trial(const std::vector<EngineIntervention>& all,
                                               double dt) {
  // A reset is the graver: the motion after it is not the scene's at all.
  if (const auto reset = intervention_of(all, EngineIntervention::Kind::Reset))
    return StabilityTrial{false, intervention_reason(*reset, dt), "diverged"};
  if (const auto cap = intervention_of(all, EngineIntervention::Kind::Cap))
    return StabilityTrial{false, intervention_reason(*cap, dt), "capped"};
  return std::nullopt;
}

}  // namespace bb
