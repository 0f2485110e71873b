// Issue 36: a rope of springs at a game's step (k = 200 N/m, 0.1 kg nodes, pinned at one end,
// let go level) on every engine. With Bullet's springs built as constraints along their
// starting direction the rope fell 78.6 m in 4 s (free fall: 78.5 m) through its own springs,
// status ok. However an engine builds its springs, an ok row hangs on them: their energy,
// sum k e^2 / 2 >= k S^2 / (2 n) for a total stretch S over n links, cannot pass the weight W
// times the depth fallen, at most n L + S; so S <= n W / k + sqrt((n W / k)^2 + 2 n^2 W L / k),
// k the softest spring the engine used (Bullet's limitIfNeeded softens them and says so).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "run/accuracy_run.hpp"
#include "support/engine_support.hpp"
#include "support/rope_case.hpp"
#include "support/test_support.hpp"

namespace bb {
namespace {

/// The softest stiffness `run`'s engine used: the one its settings name, else the case's.
double softest_stiffness(const RunRecord& run) {
  if (test::setting(run.engine_settings, "spring_stiffness_used_min"))
    return test::number_setting(run.engine_settings, "spring_stiffness_used_min");
  return test::kRopeStiffness;
}

TEST(RopeEngines, NoOkRowFallsThroughItsSprings) {
  const Scene scene = test::scene_from(test::rope_case("[0.0166666666666666667]"));
  const double n = test::kRopeLinks, length = test::kRopeLink;
  const double weight = n * test::kRopeNodeMass * scene.gravity.norm();
  int held = 0;
  for (const Backend* b : test::registry().engines()) {
    SCOPED_TRACE(b->name());
    const RunRecord run = run_accuracy(*b, scene, scene.report_dt);
    if (run.status != RunStatus::Ok) continue;
    const double k = softest_stiffness(run);
    const double stretch =
        n * weight / k + std::sqrt(std::pow(n * weight / k, 2) + 2.0 * n * n * weight * length / k);
    double deepest = 0.0;
    for (const State& s : run.trajectory.states)
      for (const BodyState& node : s)
        deepest = std::max(deepest, test::kRopeHeight - node.position.y());
    std::printf("%s: the rope's lowest node %.3f m below the anchor (at most %.3f, k %.4g N/m)\n",
                b->name().c_str(), deepest, n * length + stretch, k);
    EXPECT_LT(deepest, n * length + stretch);
    ++held;
  }
  EXPECT_GT(held, 0) << "no engine ran the rope";
}

}  // namespace
}  // namespace bb
