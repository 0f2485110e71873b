// A test-only case for [[claim]] (tests/run/claim*_test.cpp): a ball falling in drag, seen by
// two Euler integrators over a sweep of four steps; its claims judged by a real run or on
// results made up for them, and a claim's verdict for one backend.
#pragma once

#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "run/case_runner.hpp"
#include "run/claims.hpp"
#include "support/test_support.hpp"

namespace bb::test {

/// The minimal drag case over 2 s and a sweep of four steps, seen by two Euler integrators.
inline std::string fall_case() {
  std::string text = test::minimal_case("fall");
  const std::string old_time = "duration = 1.0\nsample = 0.1\ndt = [0.1, 0.05]\n";
  text.replace(text.find(old_time), old_time.size(),
               "duration = 2.0\nsample = 0.1\ndt = [0.1, 0.05, 0.025, 0.0125]\n");
  return text + R"(
[course]
integrators = ["explicit-euler", "semi-implicit-euler"]
[[observe]]
kind = "final_speed"
body = "ball"
)";
}

/// The results of fall_case() with `claims` added, judged by a run of its two integrators.
inline CaseResults judged(const std::string& claims) {
  static Scene scene;  // the results point into it
  scene = test::scene_from(fall_case() + claims);
  RunOptions options;
  options.backends = {"course/explicit-euler", "course/semi-implicit-euler"};
  options.cost = false;
  options.isolation = false;
  return run_case(scene, Registry::load(), options);
}

/// The verdict of `c` for `backend`; throws where it has none.
inline const ClaimVerdict& verdict(const ClaimResult& c, const std::string& backend) {
  for (const ClaimVerdict& v : c.verdicts)
    if (v.backend == backend) return v;
  throw std::runtime_error("no verdict for " + backend);
}

/// Results of `backend` at the four steps of fall_case(), with `final_speed/ball` measured
/// as `values[i]` (nullopt: the run diverged) and the reference's as `reference`.
inline CaseResults made_up(const Scene& scene, const std::string& backend,
                           const std::vector<std::optional<double>>& values, double reference) {
  CaseResults results;
  results.scene = &scene;
  results.reference_run.backend = "reference";
  results.reference_run.observables = {{"final_speed/ball", {reference, ""}, reference}};
  const std::vector<double> dts = {0.1, 0.05, 0.025, 0.0125};
  for (std::size_t i = 0; i < dts.size(); ++i) {
    RunRecord run;
    run.backend = backend;
    run.dt = dts[i];
    if (values[i]) {
      run.observables = {{"final_speed/ball", {*values[i], ""}, reference}};
    } else {
      run.status = RunStatus::Diverged;
    }
    results.runs.push_back(run);
  }
  return results;
}

}  // namespace bb::test
