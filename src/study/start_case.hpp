// A case's run on a backend: the seam (seam/backend.hpp) takes a World and the settings a
// backend is told, never the study; here the study fills those settings.
#pragma once

#include <memory>

#include "seam/backend.hpp"
#include "study/scene.hpp"

namespace bb {

/// The settings a case gives its backends: its engines' tables, its sample interval and its
/// observes, pointed to in `study`.
inline BackendSettings backend_settings(const Study& study) {
  return {&study.engines, study.sample, &study.observes};
}

/// Starts a run of `scene` on `backend` at step `dt`: its world, and of its study the
/// settings above only.
inline std::unique_ptr<Simulation> start_case(const Backend& backend, const Scene& scene,
                                              double dt) {
  return backend.start_run(scene, backend_settings(scene), dt);
}

}  // namespace bb
