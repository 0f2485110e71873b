// A backend sees the world and its own settings, nothing of how the case is examined: two
// cases with one world and different studies (name, length, steps, gates, claims, report,
// stability options) give every backend the same run, state for state.
#include <gtest/gtest.h>

#include <type_traits>

#include "run/registry.hpp"
#include "study/start_case.hpp"
#include "support/test_support.hpp"

namespace bb {
namespace {

// The seam's one entry point takes the World and the backend's settings.
static_assert(std::is_same_v<decltype(&Backend::start_run),
                             std::unique_ptr<Simulation> (Backend::*)(
                                 const World&, const BackendSettings&, double) const>);

/// `scene` with every part of its study changed that does not reach a backend.
Scene another_study(const Scene& scene) {
  Scene other = scene;
  other.name = "another";
  other.title = "another study of the same world";
  other.duration *= 3.0;
  other.dt = {other.dt.back()};
  other.report_dt = other.dt.back();
  other.gates.clear();
  other.claims.clear();
  other.report.target = 1.0;
  other.stability.growth_factor = 2.0;
  return other;
}

TEST(WorldOnly, EveryBackendRunsTheSameWorldTheSameWayWhateverTheStudy) {
  const Scene scene = load_case(test::source_path("cases/double_bounce.toml"));
  const Scene other = another_study(scene);
  const Registry registry = Registry::load();
  const BackendSet set = backends_for(scene, registry);
  std::vector<const Backend*> backends = set.all;
  backends.push_back(&registry.reference());
  ASSERT_GE(backends.size(), 5u);
  const double dt = scene.dt[1];
  int ran = 0;
  for (const Backend* backend : backends) {
    if (!scene.features().missing_from(backend->supports()).empty()) continue;
    ++ran;
    const auto a = start_case(*backend, scene, dt);
    const auto b = start_case(*backend, other, dt);
    State sa(scene.bodies.size()), sb(scene.bodies.size());
    for (int step = 0; step < 120; ++step) {
      a->step(), b->step();
      a->read(sa), b->read(sb);
      for (std::size_t i = 0; i < sa.size(); ++i) {
        ASSERT_EQ(sa[i].position, sb[i].position) << backend->name() << " step " << step;
        ASSERT_EQ(sa[i].velocity, sb[i].velocity) << backend->name() << " step " << step;
      }
    }
  }
  EXPECT_GE(ran, 5);  // the reference, the course's four integrators, and the engines built
}

}  // namespace
}  // namespace bb
