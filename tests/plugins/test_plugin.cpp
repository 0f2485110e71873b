// Backend plugins the loader's tests build beside the program (tests/CMakeLists.txt), one
// source compiled several ways: a working one, one that crashes as a run starts or at a
// step, one built against another interface version, one without the version symbol, one
// whose backend takes a built-in backend's name, and one of two backends (BB_TEST_SECOND). Its
// motion is gravity's closed form, so a working one's rows agree with the reference.
#include <csignal>

#include "seam/plugin_api.hpp"

namespace {

#ifndef BB_TEST_NAME
#define BB_TEST_NAME "test/falling"
#endif

/// Every body on gravity's parabola, exactly at each step.
class Falling : public bb::Simulation {
 public:
  Falling(const bb::World& world, const bb::BackendSettings&, double dt) : world_(world), dt_(dt) {
#ifdef BB_TEST_CRASH_START
    std::raise(SIGSEGV);
#endif
  }
  void step() override {
#ifdef BB_TEST_CRASH_STEP
    if (steps_ == 3) std::raise(SIGSEGV);
#endif
    ++steps_;
  }
  void read(bb::State& out) const override {
    const double t = double(steps_) * dt_;
    for (std::size_t i = 0; i < out.size(); ++i) {
      const bb::Body& b = world_.bodies[i];
      const bool moves = !b.fixed && b.mass > 0.0;
      out[i].position =
          moves ? bb::Vec3(b.position + b.velocity * t + 0.5 * world_.gravity * t * t) : b.position;
      out[i].velocity = moves ? bb::Vec3(b.velocity + world_.gravity * t) : b.velocity;
      out[i].orientation = b.orientation;
      out[i].angular_velocity = bb::Vec3::Zero();
    }
  }

 private:
  const bb::World& world_;
  double dt_;
  long steps_ = 0;
};

bb::Backend* make_backend(const char* name = BB_TEST_NAME) {
  return bb::DeclaredBackend::of<Falling>(
      {name, {bb::Feature::ThreeD, bb::Feature::Gravity}, {}, {"test", "0"}});
}

#ifdef BB_TEST_SECOND
/// The plugin's backends: the same fall under two names.
bb::Backend* make_backends(int index) {
  return index == 0 ? make_backend() : index == 1 ? make_backend(BB_TEST_SECOND) : nullptr;
}
#endif

}  // namespace

#if defined(BB_TEST_VERSION)
// Built as if against another version of the interface.
extern "C" int beachball_plugin_interface_version() {
  return BB_TEST_VERSION;
}
extern "C" bb::Backend* beachball_create_backend(int index) {
  return index == 0 ? make_backend() : nullptr;
}
#elif defined(BB_TEST_NO_VERSION)
// Built before the interface had a version: the entry point alone.
extern "C" bb::Backend* beachball_create_backend(int index) {
  return index == 0 ? make_backend() : nullptr;
}
#elif defined(BB_TEST_SECOND)
BEACHBALL_PLUGIN_BACKENDS(make_backends)
#else
BEACHBALL_PLUGIN(make_backend())
#endif
