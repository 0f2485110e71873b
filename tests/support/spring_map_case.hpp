// A small stability map the map tests share: two unit masses 1.001 m apart in the plane,
// without gravity, on an undamped spring of rest length 1 m (released at rest, stretched by
// 0.001 m: linear, the masses never pass through each other), omega = sqrt(2 k); the map is
// the spring's stiffness (up the side) by the step (along the bottom), and a run has
// exploded where its largest stretch passes ten times the start's (0.01 m).
#pragma once

#include <string>

#include "support/spring_pair_case.hpp"

namespace bb::test {

/// The map named `name` over 1 s at the stiffnesses `ks` and the steps `dts` (TOML list
/// text; each step divides the sample, 0.2 s; 0.1 among them, the report_dt), with the course
/// `integrators` (TOML list text); what the test adds ([[claim]]s) follows.
inline std::string spring_map_case(const std::string& name, const std::string& ks,
                                   const std::string& dts, const std::string& integrators) {
  return "name = \"" + name + "\"\ndims = 2\nduration = 1.0\nsample = 0.2\ndt = " + dts +
         "\nreport_dt = 0.1\ngravity = [0.0, 0.0, 0.0]\n" +
         two_masses_on_a_spring("0.5005", "100.0") + R"([[observe]]
kind = "max_stretch"
[course]
integrators = )" +
         integrators +
         R"(
[[sweep]]
parameter = "spring.1.stiffness"
onset = "max_stretch"
onset_above = 0.01
values = )" +
         ks +
         R"(
[[sweep]]
parameter = "dt"
values = )" +
         dts + "\n";
}

}  // namespace bb::test
