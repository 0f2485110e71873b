#include "report/motion_frames.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "report/motion_geometry.hpp"
#include "report/motion_view.hpp"

namespace bb::motion {

namespace {

/// Numbers the animated values may hold in all: about 40 % of the size limit.
constexpr double kNumberBudget = 0.4 * kMotionViewBytes / 6.5;
/// Frames of an animation: at least, and at most.
constexpr std::size_t kMinFrames = 20, kMaxFrames = 300;

}  // namespace

/// Whether the scene's bodies turn, so that a ball gets a mark that shows it.
bool turns(const Scene& scene) {
  return scene.features().has(Feature::Rotation);
}

/// How many numbers one frame of one run's bodies costs.
double numbers_per_frame(const Scene& scene, const std::vector<int>& drawn) {
  double n = 0.0;
  for (int b : drawn) {
    const Body& body = scene.bodies[b];
    if (body.fixed) continue;
    // A boat: five points of its hull and two of its sail.
    n += is_boat(scene, body)       ? 14
         : body.shape == Shape::Box ? (scene.dims == 2 ? 8 : 48)
                                    : (turns(scene) ? 6 : 2);
  }
  return n;
}

/// The sample indices drawn as frames: evenly spread, the first and last included.
std::vector<std::size_t> frame_samples(std::size_t samples, std::size_t frames) {
  std::vector<std::size_t> out;
  if (samples == 0) return out;
  frames = std::clamp<std::size_t>(frames, 2, std::max<std::size_t>(samples, 2));
  for (std::size_t f = 0; f < frames; ++f) {
    const std::size_t j = samples == 1 ? 0 : f * (samples - 1) / (frames - 1);
    if (out.empty() || j != out.back()) out.push_back(j);
  }
  return out;
}

/// Frames within the size limit; springs for every run if they fit, else for the reference
/// only, else none.
FrameBudget frame_budget(const Scene& scene, const std::vector<int>& drawn, std::size_t runs,
                         std::size_t springs) {
  const double bodies_each = numbers_per_frame(scene, drawn);
  const double springs_each = 4.0 * static_cast<double>(springs);
  const double n_runs = static_cast<double>(runs);
  std::size_t spring_runs = 0;
  if ((bodies_each + springs_each) * n_runs * kMinFrames <= kNumberBudget)
    spring_runs = runs;
  else if ((bodies_each * n_runs + springs_each) * kMinFrames <= kNumberBudget)
    spring_runs = 1;
  const double per_frame = std::max(1.0, bodies_each * n_runs + springs_each * spring_runs);
  const std::size_t frames = std::clamp<std::size_t>(
      static_cast<std::size_t>(kNumberBudget / per_frame), kMinFrames, kMaxFrames);
  return {frames, spring_runs};
}

std::string time_readout(double x, double width, double bar_y, double total, double play) {
  std::string svg;
  svg += fmt::format(
      "<rect x=\"{0}\" y=\"{1}\" width=\"{2}\" height=\"8\" fill=\"#eeeeee\"/>\n<rect x=\"{0}\" "
      "y=\"{1}\" width=\"0\" height=\"8\" fill=\"#777777\"><animate attributeName=\"width\" "
      "values=\"0;{2}\" dur=\"{3:.3f}s\" repeatCount=\"indefinite\"/></rect>\n",
      num(x), num(bar_y), num(width), play);
  for (int tenth = 0; tenth < 10; ++tenth) {
    const double from = tenth / 10.0, to = (tenth + 1) / 10.0;
    const std::string values = tenth == 0 ? "1;0" : tenth == 9 ? "0;1" : "0;1;0";
    const std::string times = tenth == 0   ? fmt::format("0;{:.2f}", to)
                              : tenth == 9 ? fmt::format("0;{:.2f}", from)
                                           : fmt::format("0;{:.2f};{:.2f}", from, to);
    svg += fmt::format(
        "<text x=\"{}\" y=\"{}\" opacity=\"{}\">t = {:.3g} s<animate attributeName=\"opacity\" "
        "values=\"{}\" keyTimes=\"{}\" calcMode=\"discrete\" dur=\"{:.3f}s\" "
        "repeatCount=\"indefinite\"/></text>\n",
        num(x), num(bar_y + 24.0), tenth == 0 ? 1 : 0, from * total, values, times, play);
  }
  svg += fmt::format("<text x=\"{}\" y=\"{}\" text-anchor=\"end\">{:.3g} s</text>\n</svg>\n",
                     num(x + width), num(bar_y + 24.0), total);
  return svg;
}

}  // namespace bb::motion
