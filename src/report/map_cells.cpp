#include "report/map_cells.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "run/stability.hpp"
#include "run/sweep_runner.hpp"

namespace bb {

namespace {

/// The step as a map's axis.
constexpr const char* kStep = "dt";

MapAxis axis_of(const Sweep& sweep) {
  MapAxis axis;
  axis.parameter = sweep.parameter;
  axis.index.resize(sweep.values.size());
  std::iota(axis.index.begin(), axis.index.end(), std::size_t{0});
  std::sort(axis.index.begin(), axis.index.end(),
            [&](std::size_t a, std::size_t b) { return sweep.values[a] < sweep.values[b]; });
  for (std::size_t k : axis.index) axis.values.push_back(sweep.values[k]);
  return axis;
}

}  // namespace

MapAxis map_rows(const Scene& scene) {
  return axis_of(*scene.sweep);
}

MapAxis map_columns(const Scene& scene) {
  return axis_of(*scene.second_sweep);
}

double axis_position(const MapAxis& axis, double value) {
  const std::vector<double>& v = axis.values;
  const double count = static_cast<double>(v.size());
  if (value <= v.front()) return value == v.front() ? 0.5 : 0.0;
  if (value >= v.back()) return value == v.back() ? count - 0.5 : count;
  const std::size_t k =
      static_cast<std::size_t>(std::upper_bound(v.begin(), v.end(), value) - v.begin() - 1);
  const bool logarithmic = v[k] > 0.0;
  const double a = logarithmic ? std::log(v[k]) : v[k];
  const double b = logarithmic ? std::log(v[k + 1]) : v[k + 1];
  const double x = logarithmic ? std::log(value) : value;
  return static_cast<double>(k) + 0.5 + (x - a) / (b - a);
}

std::vector<BoundaryPoint> map_boundary(const Scene& scene, const std::string& backend) {
  const bool step_first = scene.sweep->parameter == kStep;
  if (!step_first && scene.second_sweep->parameter != kStep) return {};
  const MapAxis other = step_first ? map_columns(scene) : map_rows(scene);
  // The step's value at a point does not move the theory's limit: any one will do.
  const double any_step =
      step_first ? scene.sweep->values.front() : scene.second_sweep->values.front();
  std::vector<BoundaryPoint> out;
  for (double value : other.values) {
    const Scene point = step_first ? map_point_scene(scene, any_step, value)
                                   : map_point_scene(scene, value, any_step);
    const std::optional<double> limit = theory_for(point, backend);
    if (!limit) return {};
    out.push_back({value, *limit});
  }
  return out;
}

}  // namespace bb
