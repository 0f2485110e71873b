// The fall the test plugins give: gravity's closed form, so a working plugin's rows agree
// with the reference.
#include "plugins/falling_backend.hpp"

#include <csignal>
#include <memory>

#include "seam/plugin_api.hpp"

namespace bb::test_plugin {

namespace {

/// Every body on gravity's parabola, exactly at each step.
class Falling : public Simulation {
 public:
  Falling(const World& world, const BackendSettings&, double dt, Crash crash)
      : world_(world), dt_(dt), crash_(crash) {
    if (crash_ == Crash::AtStart) std::raise(SIGSEGV);
  }
  void step() override {
    if (crash_ == Crash::AtFourthStep && steps_ == 3) std::raise(SIGSEGV);
    ++steps_;
  }
  void read(State& out) const override {
    const double t = double(steps_) * dt_;
    for (std::size_t i = 0; i < out.size(); ++i) {
      const Body& b = world_.bodies[i];
      const bool moves = !b.fixed && b.mass > 0.0;
      out[i].position =
          moves ? Vec3(b.position + b.velocity * t + 0.5 * world_.gravity * t * t) : b.position;
      out[i].velocity = moves ? Vec3(b.velocity + world_.gravity * t) : b.velocity;
      out[i].orientation = b.orientation;
      out[i].angular_velocity = Vec3::Zero();
    }
  }

 private:
  const World& world_;
  double dt_;
  Crash crash_;
  long steps_ = 0;
};

}  // namespace

Backend* falling_backend(const char* name, Crash crash) {
  return new DeclaredBackend(
      {name, {Feature::ThreeD, Feature::Gravity}, {}, {"test", "0"}},
      [crash](const World& world, const BackendSettings& settings, double dt) {
        return std::make_unique<Falling>(world, settings, dt, crash);
      });
}

int interface_version() {
  return BEACHBALL_PLUGIN_INTERFACE_VERSION;
}

}  // namespace bb::test_plugin
