// A student's integrator the course does not have: symplectic Euler (the velocity first,
// then the position with the new velocity) with a restitution hack at the floor (a ball
// found below the floor is put back on it and its normal velocity reversed, times e).
// Built outside beachball's tree against its SDK, loaded with `beachball ... --plugin`.
//
// Built with -DWORSE it keeps the old velocity for the position (explicit Euler): the same
// order, a larger error, the regression `beachball check --baseline` is there to catch.
#include <physics/step_start.hpp>
#include <seam/plugin_api.hpp>

namespace {

class SymplecticEuler : public bb::Simulation {
 public:
  SymplecticEuler(const bb::World& world, const bb::BackendSettings&, double dt)
      : world_(world), dt_(dt), start_(world, dt) {
    for (const bb::Body& b : world.bodies) state_.push_back({b.position, b.velocity});
  }

  void step() override {
    // Gravity, then the force model's loads (drag, wind, springs) from the state the step
    // starts in, as every fixed-step backend takes them.
    const bb::Loads* loads = start_.has_loads() ? &start_.loads(state_) : nullptr;
    for (std::size_t i = 0; i < state_.size(); ++i) {
      const bb::Body& body = world_.bodies[i];
      if (body.fixed || body.mass == 0.0) continue;
      bb::BodyState& s = state_[i];
      bb::Vec3 a = world_.gravity;
      if (loads) a += loads->force[i] / body.mass;
#ifdef WORSE
      s.position += s.velocity * dt_;
      s.velocity += a * dt_;
#else
      s.velocity += a * dt_;
      s.position += s.velocity * dt_;
#endif
      if (world_.ground) floor_hack(*world_.ground, body.radius, s);
    }
  }

  void read(bb::State& out) const override {
    // Nothing turns here: each body keeps the orientation it started with.
    for (std::size_t i = 0; i < state_.size(); ++i) {
      out[i].position = state_[i].position;
      out[i].velocity = state_[i].velocity;
      out[i].orientation = world_.bodies[i].orientation;
      out[i].angular_velocity = bb::Vec3::Zero();
    }
  }

  bb::Settings settings() const override {
    return {{"floor", std::string("restitution hack")}};
  }

 private:
  // Below the floor: back onto it, the normal velocity reversed and scaled by e.
  static void floor_hack(const bb::Ground& ground, double radius, bb::BodyState& s) {
    const double depth = radius - (s.position - ground.point).dot(ground.normal);
    const double approach = s.velocity.dot(ground.normal);
    if (depth <= 0.0 || approach >= 0.0) return;
    s.position += depth * ground.normal;
    s.velocity -= (1.0 + ground.restitution) * approach * ground.normal;
  }

  const bb::World& world_;
  double dt_;
  bb::StepStart start_;
  bb::State state_;
};

}  // namespace

// What it declares: the name of its rows, what it simulates (a scene using anything else is
// a row `unsupported`: nothing here turns, so no spin, torque, impulse at a point or box),
// its library and version.
BEACHBALL_PLUGIN(bb::DeclaredBackend::of<SymplecticEuler>(
    {"student/symplectic-euler",
     {bb::Feature::ThreeD, bb::Feature::Gravity, bb::Feature::Drag, bb::Feature::Wind,
      bb::Feature::GroundContact, bb::Feature::Restitution, bb::Feature::Springs},
     {},
     {"student", "1.0"}}))
