// The tunnelling tests' bodies: a 5 cm ball of 50 g flying along x at a fixed panel 2 cm thick
// (its near face at x = -0.01), restitution 0.5 between them; a test adds the time keys.
#pragma once

#include <string>

namespace bb::test {

/// The two [[body]] tables and their [[contact]]: the ball at x = `x` with speed `speed`
/// (TOML numbers as text).
inline std::string ball_and_thin_panel(const std::string& x, const std::string& speed) {
  return R"([[body]]
name = "ball"
radius = 0.05
mass = 0.05
position = [)" +
         x + R"(, 1.0, 0.0]
velocity = [)" +
         speed + R"(, 0.0, 0.0]
[[body]]
name = "panel"
shape = "box"
half_extents = [0.01, 1.0, 1.0]
mass = 1.0
fixed = true
position = [0.0, 1.0, 0.0]
[[contact]]
bodies = ["ball", "panel"]
restitution = 0.5
)";
}

}  // namespace bb::test
