// Bullet's collision pools sized to the scene. Every run is a fresh child process, and
// Bullet's default pools (4096 contact manifolds and 4096 collision algorithms, about 4 MB)
// are written through when the configuration is built: in a new process that is a page
// fault for every page, several milliseconds per run, more than a short run's steps. A
// manifold or an algorithm beyond its pool comes from the heap instead
// (btCollisionDispatcher::getNewManifold, allocateCollisionAlgorithm), so the size changes
// where they live, never what the steps compute.
#pragma once

#include <btBulletCollisionCommon.h>

#include <algorithm>

#include "model/world.hpp"

namespace bb {

/// Room for one manifold and one algorithm per pair of the scene's bodies and the ground,
/// at least 16 and at most Bullet's default of 4096.
inline btDefaultCollisionConstructionInfo pools_for(const World& scene) {
  const long objects = static_cast<long>(scene.bodies.size()) + 1;
  const int pairs = static_cast<int>(std::clamp(objects * (objects - 1) / 2, 16L, 4096L));
  btDefaultCollisionConstructionInfo info;
  info.m_defaultMaxPersistentManifoldPoolSize = pairs;
  info.m_defaultMaxCollisionAlgorithmPoolSize = pairs;
  return info;
}

}  // namespace bb
