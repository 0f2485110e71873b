#include "reference/wave_surface.hpp"

#include <cmath>
#include <string>

namespace bb {

namespace {

class WaveSurface : public Simulation {
 public:
  WaveSurface(const World& world, double dt) : waves_(*world.waves), dt_(dt) {}

  void step() override { ++steps_; }

  void read(State& out) const override {
    const double t = static_cast<double>(steps_) * dt_;
    const Waves& w = waves_;
    for (int i = 0; i < w.points; ++i) {
      const double x0 = w.rest_x(i);
      const double phase = w.speed * t + w.wavenumber * x0;
      BodyState& s = out[static_cast<std::size_t>(w.first_body + i)];
      s.position = {x0 + w.amplitude * std::cos(phase), w.level + w.amplitude * std::sin(phase),
                    0.0};
      s.velocity = {-w.amplitude * w.speed * std::sin(phase),
                    w.amplitude * w.speed * std::cos(phase), 0.0};
    }
  }

  Settings settings() const override {
    return {{"method", std::string("the formula of seed section 10, evaluated at each step's time "
                                   "t: x = x0 + amp cos(speed t + k x0), y = level + amp "
                                   "sin(speed t + k x0); nothing is integrated")}};
  }

 private:
  Waves waves_;
  double dt_;
  long steps_ = 0;
};

}  // namespace

std::unique_ptr<Simulation> start_wave_surface(const World& world, double dt) {
  return std::make_unique<WaveSurface>(world, dt);
}

}  // namespace bb
