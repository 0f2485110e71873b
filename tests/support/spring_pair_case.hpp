// A case text the map tests share: two unit masses 1.2 m apart in the plane, without gravity,
// joined by a spring of rest length 1 m and stiffness 100 N/m (omega = sqrt(2 k)).
#pragma once

#include <string>

namespace bb::test {

/// Two unit point masses named left and right at x = -`half_gap` and +`half_gap` m, joined by
/// a spring of rest length 1 m and stiffness `stiffness` N/m (TOML number text).
inline std::string two_masses_on_a_spring(const std::string& half_gap,
                                          const std::string& stiffness) {
  return "[[body]]\nname = \"left\"\nshape = \"point\"\nmass = 1.0\nposition = [-" + half_gap +
         ", 0.0, 0.0]\n[[body]]\nname = \"right\"\nshape = \"point\"\nmass = 1.0\nposition = [" +
         half_gap +
         ", 0.0, 0.0]\n[[spring]]\nbodies = [\"left\", \"right\"]\nstiffness = " + stiffness +
         "\nrest_length = 1.0\n";
}

/// The spring pair named `name`, sampled every `sample` s over 1 s at the steps `dts` (TOML
/// list text), reported at `report_dt`; what the test adds ([course], [[sweep]]s) follows.
inline std::string spring_pair_case(const std::string& name, const std::string& sample,
                                    const std::string& dts, const std::string& report_dt) {
  return "name = \"" + name + "\"\ndims = 2\nduration = 1.0\nsample = " + sample + "\ndt = " + dts +
         "\nreport_dt = " + report_dt + "\ngravity = [0.0, 0.0, 0.0]\n" +
         two_masses_on_a_spring("0.6", "100.0");
}

}  // namespace bb::test
