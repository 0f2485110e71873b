// Helpers shared by the tests: scenes from inline TOML, paths into the source tree.
#pragma once

#include <stdlib.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>

#include "files/whole_file.hpp"
#include "run/case_loading.hpp"

namespace bb::test {

/// Gravity of the tests' own scenes, m/s^2.
inline constexpr double kG = 9.81;

/// The program as a test runs it keeps no results between invocations (each run is the
/// run under test); a test of the kept results names its own folder with --cache.
inline const bool kNoKeptResults = setenv("BEACHBALL_CACHE", "off", 1) == 0;

/// The source tree, for cases/ and tests/cases/.
inline std::string source_path(const std::string& relative) {
  return std::string(BEACHBALL_SOURCE_DIR) + "/" + relative;
}

/// The bundled case cases/<name>.toml, loaded.
inline Scene bundled_case(const std::string& name) {
  return load_case(source_path("cases/" + name + ".toml"));
}

/// A file's whole content.
inline std::string bytes(const std::filesystem::path& path) {
  return read_whole_file(path.string()).value_or("");
}

/// A scene parsed from inline case text, named "inline.toml" in messages.
inline Scene scene_from(const std::string& toml) {
  return parse_case(toml, "inline.toml");
}

/// The smallest valid 2D drag case, for tests to extend.
inline const char* kMinimalCase = R"(name = "minimal"
dims = 2
duration = 1.0
sample = 0.1
dt = [0.1, 0.05]
report_dt = 0.05

[air]
density = 1.2

[[body]]
name = "ball"
radius = 0.5
mass = 1.0
position = [0.0, 10.0, 0.0]
drag_coefficient = 0.47
)";

/// kMinimalCase named `name`.
inline std::string minimal_case(const std::string& name) {
  std::string text = kMinimalCase;
  text.replace(text.find("\"minimal\""), 9, "\"" + name + "\"");
  return text;
}

/// kMinimalCase named `name` made slow: 10 bodies over 1000 simulated seconds in 10 million
/// steps, so each run's child works for seconds and the whole run for tens of seconds.
inline std::string slow_case(const std::string& name) {
  std::string text = minimal_case(name);
  for (const auto& [from, to] :
       {std::pair<std::string, std::string>{"duration = 1.0", "duration = 1000.0"},
        {"sample = 0.1", "sample = 0.01"},
        {"dt = [0.1, 0.05]", "dt = [0.0001]"},
        {"report_dt = 0.05", "report_dt = 0.0001"}})
    text.replace(text.find(from), from.size(), to);
  for (int body = 1; body < 10; ++body)
    text += "\n[[body]]\nname = \"ball" + std::to_string(body) +
            "\"\nradius = 0.5\nmass = 1.0\nposition = [" + std::to_string(body) +
            ".0, 10.0, 0.0]\ndrag_coefficient = 0.47\n";
  return text;
}

/// Two balls stacked on the ground, touching at the start: a case the reference has no
/// exact answer for, with a sweep of three steps.
inline const char* kStackedBalls = R"(name = "stack"
dims = 2
duration = 1.0
sample = 0.0166666666666666667
dt = [0.0166666666666666667, 0.00833333333333333333, 0.00416666666666666667]
report_dt = 0.0166666666666666667
[ground]
restitution = 0.5
[[body]]
name = "low"
radius = 0.5
mass = 1.0
position = [0.0, 0.5, 0.0]
[[body]]
name = "high"
radius = 0.5
mass = 1.0
position = [0.0, 1.5, 0.0]
[[contact]]
bodies = ["low", "high"]
restitution = 0.5
)";

/// A 1 m, 1 kg cube resting on a level ground at x: a case's [[body]] entry.
inline std::string resting_box(const std::string& name, double x) {
  return "[[body]]\nname = \"" + name +
         "\"\nshape = \"box\"\nhalf_extents = [0.5, 0.5, 0.5]\nmass = 1.0\nposition = [" +
         std::to_string(x) + ", 0.5, 0.0]\n";
}

/// A 2D case head of `name` with one step of 0.1 s over 1 s and a level ground whose
/// friction section is `ground` (the lines after [ground]).
inline std::string level_ground_case(const std::string& name, const std::string& ground) {
  return "name = \"" + name +
         "\"\ndims = 2\nduration = 1.0\nsample = 0.1\ndt = [0.1]\nreport_dt = 0.1\n[ground]\n" +
         ground;
}

/// A free ball in 2D without gravity, turned `angle` degrees and spinning at `spin` rad/s
/// about z for 2 s, sampled every half second, stepped at 1/30 s, its final_angle observed.
inline std::string spinning_ball_case(double spin, double angle) {
  return std::string(R"(name = "spin"
dims = 2
duration = 2.0
sample = 0.5
dt = [0.0333333333333333333]
report_dt = 0.0333333333333333333
gravity = [0.0, 0.0, 0.0]
[[body]]
name = "ball"
radius = 0.5
mass = 1.0
position = [0.0, 2.0, 0.0]
angle = )") +
         std::to_string(angle) + "\nangular_velocity = [0.0, 0.0, " + std::to_string(spin) +
         "]\n[[observe]]\nkind = \"final_angle\"\nbody = \"ball\"\n";
}

/// A 2 kg cube at rest on level ground (mu_s 0.4, mu_k 0.3), stepped at 1/60 s for 3 s,
/// given `impulses` ([[impulse]] tables) and its stop_time, stop_distance and rest_creep
/// observed.
inline std::string pushed_block_case(const std::string& impulses) {
  return R"(name = "pushed"
dims = 2
duration = 3.0
sample = 0.0333333333333333333
dt = [0.0166666666666666667]
report_dt = 0.0166666666666666667
[ground]
friction_static = 0.4
friction_kinetic = 0.3
[[body]]
name = "block"
shape = "box"
half_extents = [0.5, 0.5, 0.5]
mass = 2.0
position = [0.0, 0.5, 0.0]
)" + impulses +
         R"(
[[observe]]
kind = "stop_time"
body = "block"
[[observe]]
kind = "stop_distance"
body = "block"
[[observe]]
kind = "rest_creep"
body = "block"
)";
}

}  // namespace bb::test
