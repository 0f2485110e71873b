// The air forces of section 8 of the course text, as every backend applies them.
#pragma once

#include "scene/scene.hpp"

namespace bb {

/// Quadratic drag F = -1/2 Cd A rho |v - w| (v - w), A = pi r^2 (newtons).
Vec3 drag_force(const Body& body, const Air& air, const Vec3& velocity);

/// Magnus force F = k (omega x (v - w)) (newtons).
Vec3 magnus_force(const Body& body, const Air& air, const Vec3& velocity, const Vec3& omega);

/// Sum of drag and Magnus on a body; zero when the scene has no air.
Vec3 air_force(const Scene& scene, const Body& body, const Vec3& velocity, const Vec3& omega);

}  // namespace bb
