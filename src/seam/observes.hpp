// What a case asks to observe ([[observe]]): the study reads it, and a backend is told it
// (BackendSettings, seam/backend.hpp): the reference locates the events it needs exactly.
#pragma once

#include <optional>
#include <string>

#include "model/vec3.hpp"

namespace bb {

/// A case-specific quantity to report, e.g. terminal_velocity of one body.
struct Observe {
  std::string kind;
  int body = -1;
  int n = 0;  ///< for counted kinds (the n-th bounce), else 0
  int line = 0;
  /// `<kind>/<body>` or `<kind>/<body>/<n>`, as results name it.
  std::string name;
  /// m/s: the body counts as at rest below this speed (its stops, its drift angle), for the
  /// kinds that take it; none: the kind's default, scaled from the run (observables.md).
  std::optional<double> rest_speed = std::nullopt;
  /// The unit axis a signed spin is read about (post_angular_velocity): +z unless given in
  /// 2D, given in 3D.
  Vec3 axis{0.0, 0.0, 1.0};
  /// m: the height along -gravity whose crossings the kind watches (time_above), for the
  /// kinds that take it.
  std::optional<double> level = std::nullopt;
};

}  // namespace bb
