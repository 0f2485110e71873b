#include "reference/wave_surface.hpp"

#include <string>
#include <tuple>

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
      BodyState& s = out[static_cast<std::size_t>(w.first_body + i)];
      std::tie(s.position, s.velocity) = wave_motion(w, i, t);
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
