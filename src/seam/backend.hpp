// The seam every simulator sits behind: a Backend starts a Simulation of one scene
// at one fixed step; the runner steps it and reads its state.
#pragma once

#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "model/features.hpp"
#include "model/state.hpp"
#include "model/world.hpp"
#include "seam/engine_tables.hpp"
#include "seam/event_trace.hpp"
#include "seam/observes.hpp"

namespace bb {

/// A value an engine setting took in a run: a number, a switch or a description.
using SettingValue = std::variant<double, bool, std::string>;
/// Every engine parameter that changes results, as actually used, in a stable order.
using Settings = std::vector<std::pair<std::string, SettingValue>>;

/// Thrown by Backend::start (or a step) when a scene uses something this backend cannot
/// simulate in a way its feature set does not capture (the reference past an exact answer,
/// a course rule that acts against the ground only): the run is `unsupported`, with the
/// message as its reason.
struct UnsupportedScene : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// Something an engine did to a run that its state does not show, as the engine reports it:
/// what it means for the run (a divergence, a row not to be trusted) is the runner's to say.
struct EngineIntervention {
  enum class Kind {
    /// The engine threw its state away and started again (MuJoCo resets its data to the
    /// initial state on a bad acceleration): what follows is not the scene's motion.
    Reset,
    /// The engine held something at a limit of its own that the scene does not have (Box2D
    /// moves a body at most 2 m per step): the motion goes on, bounded by the engine.
    Cap,
  };
  Kind kind = Kind::Reset;
  /// Steps completed before the one in which the engine did it: it happened at t = step * dt
  /// (seconds), and shows in the state after step + 1.
  long step = 0;
  /// What the engine did, with the body and the limit where there is one, in words that can
  /// be followed by when ("MuJoCo reset its state", "Box2D held body 'wall' at its cap of
  /// 2 m per step (40 m/s at dt 0.05 s)").
  std::string what;
  /// The engine's own reason, its warning or constant ("mjWARN_BADQACC: ..."); may be empty.
  std::string cause;
};

/// One scene advancing at one fixed step.
class Simulation {
 public:
  virtual ~Simulation() = default;
  /// Advance by dt.
  virtual void step() = 0;
  /// Copy the current state of every body into `out` (resized by the caller to the body count).
  virtual void read(State& out) const = 0;
  /// The engine settings this run used.
  virtual Settings settings() const { return {}; }
  /// Contacts and apexes located exactly (the reference); nullopt for a backend whose
  /// events the runner finds from its state at every step.
  virtual std::optional<EventTrace> exact_events() const { return std::nullopt; }
  /// Steps an adaptive solver took internally so far; nullopt for fixed-step backends.
  virtual std::optional<long> internal_steps() const { return std::nullopt; }
  /// What the engine did that its state does not show, each kind latched at the first time
  /// it happened (at most one Reset and one Cap, in the order they happened); empty for a
  /// backend whose state tells everything. Cheap: the runner reads it at every sample.
  virtual std::vector<EngineIntervention> interventions() const { return {}; }
};

/// What a backend is told besides the world, all from the case's study, which fills it
/// (study/start_case.hpp: the seam never sees the study): the engines' settings tables (each
/// engine reads its own [engines.<engine>]) and, for the reference, the sample interval (its
/// stiffness bound) and the observes whose events it locates exactly. The pointers point
/// into the case, which outlives every run.
struct BackendSettings {
  const EngineTables* engines = nullptr;
  double sample = 0.0;
  const std::vector<Observe>* observes = nullptr;

  /// The observes, none when not given.
  const std::vector<Observe>& observed() const {
    static const std::vector<Observe> none;
    return observes ? *observes : none;
  }
};

class Backend {
 public:
  virtual ~Backend() = default;
  /// "bullet", "course/velocity-verlet", "reference", ...
  virtual std::string name() const = 0;
  virtual FeatureSet supports() const = 0;
  /// Features a scene must use for this backend to take part at all: a second way of
  /// building the same physics (`box2d/force`, springs applied by hand) is the base engine
  /// on a scene without them, so it is left out there. Default: none.
  virtual FeatureSet needs() const { return {}; }
  /// Library and version, e.g. {"bullet", "3.24"}; empty name for none.
  virtual std::pair<std::string, std::string> library_version() const { return {}; }
  /// Start a run of `world` at step `dt`, told only `settings` of the study; the world and
  /// what the settings point to outlive the simulation.
  virtual std::unique_ptr<Simulation> start_run(const World& world, const BackendSettings& settings,
                                                double dt) const = 0;
};

}  // namespace bb
