// Drawing a scene on a page: the view plane (a 3D scene seen obliquely), a canvas with one
// scale for both axes, and each thing of the scene as SVG: the ground, the fixed bodies and
// hinges, a body's outline at a state, the springs. For the motion view (motion_view.hpp).
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "metrics/trajectory.hpp"
#include "study/scene.hpp"

namespace bb::motion {

struct Point2 {
  double x = 0.0, y = 0.0;
};

/// The view plane: x to the right and y up; a 3D scene is seen obliquely, its z axis going
/// back up and to the right at half length.
Point2 project(const Scene& scene, const Vec3& p);

/// Pixels from the world: one scale for both axes, y pointing down on the page.
struct Canvas {
  double x0 = 0.0, y1 = 0.0, scale = 1.0, width = 0.0, height = 0.0;
  Point2 px(Point2 w) const { return {(w.x - x0) * scale, (y1 - w.y) * scale}; }
  double len(double metres) const { return metres * scale; }
};

/// A number as the SVG writes it: one decimal.
std::string num(double v);

/// A canvas `width` pixels wide (its top left at 0, 0) showing what the `framed` runs cover,
/// the fixed bodies and the ground's point, with a margin; its height between the two
/// bounds (the world shown widens to keep one scale).
Canvas fit(const Scene& scene, const std::vector<const Trajectory*>& framed,
           const std::vector<int>& drawn, double width, double min_height, double max_height);

/// Whether `body` is drawn as a boat: a box with a sail, seen from above.
bool is_boat(const Scene& scene, const Body& body);
/// The wind as an arrow in the canvas's top left, with its speed, sized by `thick` (small
/// panels); "" without wind.
std::string wind_svg(const Scene& scene, const Canvas& c, double thick);

/// The ground as a line with the half-space below it shaded.
std::string ground_svg(const Scene& scene, const Canvas& c);
/// The fixed bodies and the hinges' anchors, drawn once.
std::string fixed_svg(const Scene& scene, const Canvas& c);

/// A body's outline at one state: a circle's centre and radius (and, for a turning ball, a
/// path marking its turn), or a box's path; a boat's hull pointed at its bow, and its sail.
struct Outline {
  bool circle = false;
  Point2 centre;
  double radius = 0.0;
  std::string path;
};
Outline outline(const Scene& scene, const Body& body, const BodyState& state, const Canvas& c,
                bool mark_turn);

/// The springs whose two bodies are drawn, as pairs of slots in `drawn`.
std::vector<std::pair<std::size_t, std::size_t>> drawn_springs(const Scene& scene,
                                                               const std::vector<int>& drawn);
/// The path of those springs at one state.
std::string springs_path(const Scene& scene, const State& s,
                         const std::vector<std::pair<std::size_t, std::size_t>>& springs,
                         const Canvas& c);

}  // namespace bb::motion
