// What the motion view frames, and what it marks: the view frames every run's bodies but a
// diverged run's and a run far off the reference's scale (off_scale.hpp: a run at 1e30 m
// would shrink the others to nothing), and a body that leaves the frame (a block that slides away
// on one engine, a run that went to NaN) gets an arrow at the edge where it left, with its name and
// the time, and the title names each such run with where it went: the picture never hides
// a backend's failure.
#pragma once

#include <string>
#include <vector>

#include "report/motion_geometry.hpp"
#include "run/results.hpp"

namespace bb::motion {

/// Per run, whether it diverged or is off the guide's scale: the view frames the others.
std::vector<bool> off_frame(const Scene& scene, const std::vector<const RunRecord*>& runs,
                            const std::vector<int>& drawn, const Trajectory& guide);

/// A body of a run leaving the canvas: when, where on the edge (pixels) and which way.
struct FrameExit {
  std::size_t run = 0, slot = 0;
  double time = 0.0;
  Point2 edge, direction;  ///< direction: a unit vector on the page
};

/// Every body of every run that leaves `c`: the first sample at which its centre lies
/// outside the canvas or is not finite.
std::vector<FrameExit> frame_exits(const Scene& scene, const std::vector<const RunRecord*>& runs,
                                   const std::vector<int>& drawn, const Canvas& c);

/// The arrows of `exits` of run `run` (all runs when `run` is runs.size()), each in its
/// run's colour, the run's first with the body's name and the time, at most a dozen a run,
/// lines scaled by `thick`. Animated (`play`
/// > 0): each appears when its body leaves, over a loop of `play` seconds showing `total`
/// simulated ones. A still (`play` = 0): those that left by `instant`.
struct MarkTiming {
  double total = 0.0, play = 0.0, instant = 0.0;
};
std::string exit_marks_svg(const Scene& scene, const std::vector<const RunRecord*>& runs,
                           const std::vector<int>& drawn, const std::vector<FrameExit>& exits,
                           std::size_t run, const Canvas& c, double thick, MarkTiming timing);

/// Per run with a body off the frame, a line for the title: its first body to leave, when,
/// how many more, and the farthest point its bodies reach (or that they went to NaN).
std::vector<std::string> exit_notes(const Scene& scene, const std::vector<const RunRecord*>& runs,
                                    const std::vector<int>& drawn,
                                    const std::vector<FrameExit>& exits, const Canvas& c);

}  // namespace bb::motion
