// How a backend is drawn, the same on every plot and page of a report: a colour of its own
// (a course integrator's variants take shades of the integrator's colour), far enough from
// every other that can share its plot to tell apart on a projector, and a line kind
// that tells the reference, the course methods and the engines apart.
#pragma once

#include <string>

namespace bb {

enum class LineKind { Reference, Course, Engine };

struct BackendStyle {
  std::string colour;  ///< "#rrggbb"
  LineKind kind = LineKind::Engine;
  bool named = false;  ///< its colour is listed for it, not a spare picked by its name's hash
};

/// The style of `backend` ("reference", "course/rk4+clamp", "ode/force", ...): a pure
/// function of the name.
BackendStyle backend_style(const std::string& backend);

}  // namespace bb
