// A test-only scene for the friction map's tests: a unit cube of 1 kg at rest on level
// ground (mu_s 0.6, mu_k 0.25, no bounce), its final velocity observed, seen by the course's
// semi-implicit Euler; a test adds its [[sweep]]s (the ground's tilt, its mu_s) and claims.
#pragma once

#include <string>

namespace bb::test {

/// The scene's text, named `name`; `course_rules` are more keys of its [course] table.
inline std::string block_on_ground_case(const std::string& name,
                                        const std::string& course_rules = "") {
  return "name = \"" + name + R"("
dims = 2
duration = 1.0
sample = 0.1
dt = [0.1, 0.05]
report_dt = 0.05
[ground]
restitution = 0.0
friction_static = 0.6
friction_kinetic = 0.25
[[body]]
name = "block"
shape = "box"
half_extents = [0.5, 0.5, 0.5]
mass = 1.0
position = [0.0, 0.5, 0.0]
[course]
integrators = ["semi-implicit-euler"]
)" + course_rules +
         R"([[observe]]
kind = "final_velocity"
body = "block"
)";
}

}  // namespace bb::test
