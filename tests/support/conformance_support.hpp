// The backends a property of motion is checked on (tests/conformance/): the reference, every
// course integrator and every engine backend of the catalogue, each run on a scene or
// skipped with the reason (its description lacks a feature; its plugin was not built, which
// fails where BEACHBALL_REQUIRE_ALL is set).
#pragma once

#include <algorithm>
#include <optional>
#include <string>
#include <vector>

#include "run/accuracy_run.hpp"
#include "run/engine_catalogue.hpp"
#include "study/backend_names.hpp"
#include "support/engine_support.hpp"

namespace bb::test {

/// Every course integrator, so that each is a variant of a scene it is appended to.
inline const char* kEveryIntegrator = R"(
[course]
integrators = ["explicit-euler", "semi-implicit-euler", "velocity-verlet", "rk4"]
)";

/// The reference, the four course integrators and every engine backend the catalogue holds.
inline std::vector<std::string> every_backend() {
  std::vector<std::string> names = {"reference", "course/explicit-euler",
                                    "course/semi-implicit-euler", "course/velocity-verlet",
                                    "course/rk4"};
  for (const std::string& name : engine_backend_names(engine_catalogue())) names.push_back(name);
  return names;
}

/// Backend `name`'s run of `scene` at step `dt` (the reference at its samples), or nullopt
/// with `skipped` saying why it cannot run it.
inline std::optional<RunRecord> run_backend(const std::string& name, const Scene& scene, double dt,
                                            std::string& skipped) {
  const std::string why = why_backend_cannot_run(scene, name, engine_catalogue());
  if (!why.empty()) {
    skipped = name + " cannot run this scene: " + why;
    return std::nullopt;
  }
  if (name == "reference") return run_accuracy(registry().reference(), scene, scene.sample);
  const BackendSet set = backends_for(scene, registry());
  const auto found = std::find_if(set.all.begin(), set.all.end(),
                                  [&](const Backend* b) { return b->name() == name; });
  if (found == set.all.end() && !described_but_not_built(name)) {
    skipped = name + " is not among this scene's backends";
    return std::nullopt;
  }
  if (found == set.all.end()) {
    // Skipped by the caller; where everything is required (CI), a failure first.
    skipped = not_built({name});
    if (everything_required())
      ADD_FAILURE() << skipped << " (BEACHBALL_REQUIRE_ALL is set: nothing may be missing)";
    return std::nullopt;
  }
  return run_accuracy(**found, scene, dt);
}

}  // namespace bb::test
