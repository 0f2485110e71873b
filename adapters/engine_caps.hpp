// How an adapter sees that its engine held a body at a cap of its own: a limit on how far a
// body moves or turns in one step (Box2D's b2_maxTranslation and b2_maxRotation, Bullet's
// ANGULAR_MOTION_THRESHOLD). Box2D scales a faster velocity down so that the body moves
// exactly the cap in the step, so a body held there leaves the step moving at the cap, to the
// rounding of the engine's arithmetic (a free body slower than that by more than the rounding
// is not held); Bullet keeps the spin and turns the orientation by less, so its body leaves
// the step faster than the cap. The first body seen at or past a cap is reported as a Cap
// (seam/backend.hpp).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "model/text.hpp"
#include "model/world.hpp"
#include "seam/backend.hpp"

namespace bb {

/// One cap on a body's motion per step.
struct StepCap {
  const char* engine;    ///< "Box2D"
  const char* action;    ///< what it does to the body, before its name: "held body"
  const char* limit;     ///< after the name, before the cap: "at its cap of"
  double per_step;       ///< the cap: metres (or radians) per step
  const char* size;      ///< the cap in words, "2 m" or "pi/2 rad"
  const char* unit;      ///< of the speed it allows: "m/s" or "rad/s"
  const char* constant;  ///< the engine's own name and rule, "b2_maxTranslation: ..."
};

/// Latches the first step at which a body was held at one of an engine's caps.
class CapWatch {
 public:
  /// A run of `world` at step `dt`, in arithmetic of machine epsilon `epsilon`.
  CapWatch(const World& world, double dt, double epsilon)
      : world_(world), dt_(dt), epsilon_(epsilon) {}

  /// Whether a cap has been seen: the adapter then need not look again.
  bool held() const { return !seen_.empty(); }

  /// After step number `steps` (1 for the first): body `body` left it moving at `speed`
  /// (m/s, or rad/s for a turn) under `cap`. Held means at the cap or past it, to 16
  /// roundings: the engine's scaling rounds a few times, a free body is that close to the cap
  /// by chance only.
  void check(const StepCap& cap, std::size_t body, double speed, long steps) {
    if (held() || speed * dt_ < cap.per_step * (1.0 - 16.0 * epsilon_)) return;
    seen_.push_back({EngineIntervention::Kind::Cap, steps - 1,
                     std::string(cap.engine) + " " + cap.action + " '" + world_.bodies[body].name +
                         "' " + cap.limit + " " + cap.size + " per step (" +
                         significant_digits(cap.per_step / dt_, 4) + " " + cap.unit + " at dt " +
                         format_dt(dt_) + " s)",
                     cap.constant});
  }

  const std::vector<EngineIntervention>& interventions() const { return seen_; }

 private:
  const World& world_;
  double dt_;
  double epsilon_;
  std::vector<EngineIntervention> seen_;
};

}  // namespace bb
