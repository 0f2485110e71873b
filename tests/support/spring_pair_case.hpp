// A case text the map tests share: two unit masses 1.2 m apart in the plane, without gravity,
// joined by a spring of rest length 1 m and stiffness 100 N/m (omega = sqrt(2 k)).
#pragma once

#include <string>

namespace bb::test {

/// The spring pair named `name`, sampled every `sample` s over 1 s at the steps `dts` (TOML
/// list text), reported at `report_dt`; what the test adds ([course], [[sweep]]s) follows.
inline std::string spring_pair_case(const std::string& name, const std::string& sample,
                                    const std::string& dts, const std::string& report_dt) {
  return "name = \"" + name + "\"\ndims = 2\nduration = 1.0\nsample = " + sample + "\ndt = " + dts +
         "\nreport_dt = " + report_dt + R"(
gravity = [0.0, 0.0, 0.0]
[[body]]
name = "left"
shape = "point"
mass = 1.0
position = [-0.6, 0.0, 0.0]
[[body]]
name = "right"
shape = "point"
mass = 1.0
position = [0.6, 0.0, 0.0]
[[spring]]
bodies = ["left", "right"]
stiffness = 100.0
rest_length = 1.0
)";
}

}  // namespace bb::test
