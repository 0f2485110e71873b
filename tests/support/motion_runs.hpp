// Runs made up for the motion view's tests (tests/report/motion_view*_test.cpp): bodies that
// fall or slide by a formula, and the points an SVG path goes through.
#pragma once

#include <cstdlib>
#include <string>
#include <utility>
#include <vector>

#include "run/drawn_bodies.hpp"
#include "run/results.hpp"

namespace bb::test {

/// A run at report_dt whose bodies fall from their start, `lag` behind free fall, for
/// `samples` samples.
inline RunRecord falling_run(const Scene& scene, const std::string& backend, std::size_t samples,
                             double lag) {
  RunRecord run;
  run.backend = backend;
  if (backend != "reference") run.dt = scene.report_dt;
  const std::vector<int> drawn = drawn_bodies(scene);
  for (std::size_t j = 0; j < samples; ++j) {
    const double t = j * scene.sample;
    run.trajectory.times.push_back(t);
    State s;
    for (int b : drawn) {
      BodyState body;
      body.position = scene.bodies[b].position;
      if (!scene.bodies[b].fixed) body.position.y() -= 0.5 * 9.81 * t * t * (1.0 - lag);
      s.push_back(body);
    }
    run.trajectory.states.push_back(s);
  }
  return run;
}

/// A run whose block slides along the ground to `to` metres, at an even speed.
inline RunRecord sliding_run(const Scene& scene, const std::string& backend, double to) {
  RunRecord run;
  run.backend = backend;
  if (backend != "reference") run.dt = scene.report_dt;
  for (std::size_t j = 0; j <= 200; ++j) {
    const double t = j * scene.sample;
    BodyState block;
    block.position = scene.bodies[0].position + Vec3(to * t / scene.duration, 0.0, 0.0);
    run.trajectory.times.push_back(t);
    run.trajectory.states.push_back({block});
  }
  return run;
}

/// Every "x y" pair of numbers after an M or an L in `text` (path data, in order).
inline std::vector<std::pair<double, double>> points_of(const std::string& text) {
  std::vector<std::pair<double, double>> out;
  for (std::size_t at = 0; at < text.size();) {
    const std::size_t m = text.find_first_of("ML", at);
    if (m == std::string::npos) break;
    char* end = nullptr;
    const double x = std::strtod(text.c_str() + m + 1, &end);
    if (end != text.c_str() + m + 1 && *end == ' ') {
      char* end_y = nullptr;
      const double y = std::strtod(end + 1, &end_y);
      if (end_y != end + 1) out.push_back({x, y});
    }
    at = m + 1;
  }
  return out;
}

}  // namespace bb::test
