// The motion view's frames: how many a view holds within its size limit, which samples
// they show, and the time readout that plays over them.
#pragma once

#include <string>
#include <vector>

#include "study/scene.hpp"

namespace bb::motion {

/// Whether the scene's bodies turn, so that a ball gets a mark that shows it.
bool turns(const Scene& scene);

/// How many numbers one frame of one run's bodies costs.
double numbers_per_frame(const Scene& scene, const std::vector<int>& drawn);

/// The sample indices drawn as frames: evenly spread, the first and last included.
std::vector<std::size_t> frame_samples(std::size_t samples, std::size_t frames);

/// How many frames the motion view holds, and for how many runs it draws springs.
struct FrameBudget {
  std::size_t frames = 0;
  std::size_t spring_runs = 0;
};

/// Frames within the size limit for `runs` runs of `drawn` bodies and `springs` springs;
/// springs for every run if they fit, else for the reference only, else none.
FrameBudget frame_budget(const Scene& scene, const std::vector<int>& drawn, std::size_t runs,
                         std::size_t springs);

/// The time readout at height `bar_y` from `x`, `width` wide: a bar that fills over the run
/// and the time in tenths of it, over a loop of `play` seconds showing `total` simulated ones.
std::string time_readout(double x, double width, double bar_y, double total, double play);

}  // namespace bb::motion
