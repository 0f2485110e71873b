// The hybrid integrator places events where the closed form says, applies resets there,
// and lands exactly on the requested times.
#include "reference/hybrid_integrator.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace bb {
namespace {

/// A ball of radius r bouncing on the floor y = 0 with restitution e; y = {height, velocity}.
/// Event 0 is the contact (height - r), event 1 the apex (the velocity turning negative).
class BouncingBall : public HybridModel {
 public:
  BouncingBall(double g, double r, double e) : g_(g), r_(r), e_(e) {}
  std::size_t dimension() const override { return 2; }
  void derivatives(double, const double* y, double* dydt) override {
    dydt[0] = y[1];
    dydt[1] = -g_;
  }
  std::size_t event_count() const override { return 2; }
  void events(double, const double* y, double* g) override {
    g[0] = y[0] - r_;
    g[1] = y[1];
  }
  void apply(std::size_t k, double, double* y) override {
    if (k == 0) y[1] = -e_ * y[1];
    if (k == 1) apexes.push_back(y[0]);
  }
  std::vector<double> apexes;

 private:
  double g_, r_, e_;
};

TEST(HybridIntegrator, BounceTimesAndApexesMatchTheClosedFormTo1e9) {
  const double g = 9.81, r = 0.5, h = 10.0, e = 0.8;
  BouncingBall ball(g, r, e);
  HybridIntegrator integrator(ball, {}, {h, 0.0});
  // Samples every 1/30 s, as a case would ask.
  for (int i = 1; i <= 300; ++i) integrator.advance_to(i / 30.0);
  EXPECT_EQ(integrator.time(), 10.0);

  // Contact n (0-based) at t_0 = sqrt(2 (h - r) / g), then every 2 e^n v_0 / g.
  const double v0 = std::sqrt(2.0 * g * (h - r));
  double contact = v0 / g;
  int n = 0;
  for (const EventRecord& event : integrator.events()) {
    if (event.index != 0) continue;
    EXPECT_NEAR(event.time, contact, 1e-9) << "contact " << n;
    contact += 2.0 * std::pow(e, n + 1) * v0 / g;
    ++n;
  }
  EXPECT_GE(n, 4);
  // Apex n (1-based) at r + (h - r) e^(2n).
  ASSERT_GE(ball.apexes.size(), 3u);
  for (std::size_t i = 0; i < ball.apexes.size(); ++i)
    EXPECT_NEAR(ball.apexes[i], r + (h - r) * std::pow(e, 2.0 * (i + 1)), 1e-9) << "apex " << i;
}

TEST(HybridIntegrator, WithoutEventsItIsTheSmoothSolution) {
  BouncingBall ball(9.81, -1e9, 1.0);  // the floor is far below: nothing happens but apexes
  HybridIntegrator integrator(ball, {}, {0.0, 0.0});
  integrator.advance_to(2.0);
  EXPECT_NEAR(integrator.state()[0], -0.5 * 9.81 * 4.0, 1e-9);
  EXPECT_NEAR(integrator.state()[1], -9.81 * 2.0, 1e-9);
}

TEST(HybridIntegrator, AStiffMethodPlacesEventsToo) {
  HybridOptions options;
  options.method = gsl_odeiv2_step_msbdf;
  BouncingBall ball(9.81, 0.5, 0.5);
  HybridIntegrator integrator(ball, options, {2.0, 0.0});
  integrator.advance_to(1.0);
  ASSERT_FALSE(integrator.events().empty());
  EXPECT_NEAR(integrator.events().front().time, std::sqrt(2.0 * 1.5 / 9.81), 1e-9);
}

}  // namespace
}  // namespace bb
