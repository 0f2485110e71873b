// Test backends whose stability is a given function of the step: the state turns NaN on
// the first step where the step is unstable. Each start may be written down (in a file, so
// that starts in child processes count too).
#pragma once

#include <cmath>
#include <fstream>
#include <memory>
#include <string>

#include "model/motion.hpp"
#include "seam/backend.hpp"

namespace bb::test {

/// A backend whose state turns NaN on the first step when `unstable(dt)`; with a `log`
/// file, each start appends its dt there.
class VerdictBackend : public Backend {
 public:
  std::string name() const override { return "threshold"; }
  FeatureSet supports() const override { return {Feature::Gravity, Feature::Drag}; }
  std::unique_ptr<Simulation> start_run(const World& scene, const BackendSettings&,
                                        double dt) const override {
    struct Sim : Simulation {
      State state;
      bool blow_up = false;
      void step() override {
        if (blow_up) state[0].position.y() = NAN;
      }
      void read(State& out) const override { out = state; }
    };
    if (!log.empty()) std::ofstream(log, std::ios::app) << dt << "\n";
    auto sim = std::make_unique<Sim>();
    sim->state.resize(scene.bodies.size());
    for (std::size_t i = 0; i < scene.bodies.size(); ++i)
      sim->state[i].position = scene.bodies[i].position;
    sim->blow_up = unstable(dt);
    return sim;
  }
  std::string log;  ///< a file each start appends its dt to, or "" for none

 protected:
  virtual bool unstable(double dt) const = 0;
};

/// Unstable above one step.
class ThresholdBackend : public VerdictBackend {
 public:
  explicit ThresholdBackend(double critical) : critical_(critical) {}

 private:
  bool unstable(double dt) const override { return dt > critical_; }
  double critical_;
};

/// Stable up to `a`, unstable up to `b`, stable again up to `c`, unstable above: explicit
/// Euler on a damped spring whose fold caps the energy, in caricature.
class BandBackend : public VerdictBackend {
 public:
  BandBackend(double a, double b, double c) : a_(a), b_(b), c_(c) {}

 private:
  bool unstable(double dt) const override { return (dt > a_ && dt <= b_) || dt > c_; }
  double a_, b_, c_;
};

}  // namespace bb::test
