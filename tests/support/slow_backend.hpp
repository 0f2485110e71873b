// A test backend whose every step takes at least a given time on the steady clock: the cost
// pass, the stability trials and the runs time their steps with it.
#pragma once

#include <chrono>
#include <memory>
#include <string>
#include <utility>

#include "model/motion.hpp"
#include "seam/backend.hpp"

namespace bb::test {

/// A backend whose every step takes at least `step_seconds` of the clock, counting its starts.
class SlowBackend : public Backend {
 public:
  explicit SlowBackend(double step_seconds) : step_seconds_(step_seconds) {}
  std::string name() const override { return "test/slow"; }
  FeatureSet supports() const override {
    return {Feature::ThreeD, Feature::Gravity, Feature::Drag};
  }
  std::unique_ptr<Simulation> start_run(const World& world, const BackendSettings&,
                                        double) const override {
    ++starts;
    return std::make_unique<Run>(step_seconds_, initial_state(world));
  }
  mutable int starts = 0;

 private:
  struct Run : Simulation {
    Run(double step_seconds, State start) : step_seconds(step_seconds), start(std::move(start)) {}
    void step() override {
      const auto until =
          std::chrono::steady_clock::now() + std::chrono::duration<double>(step_seconds);
      while (std::chrono::steady_clock::now() < until) {
      }
    }
    /// The bodies stay where they start.
    void read(State& out) const override { out = start; }
    double step_seconds;
    State start;
  };
  double step_seconds_;
};

}  // namespace bb::test
