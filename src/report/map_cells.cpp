#include "report/map_cells.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "run/sweep_runner.hpp"

namespace bb {

namespace {

/// Whether ascending `v` are evenly spaced, to a millionth of their span (a range's values).
bool evenly_spaced(const std::vector<double>& v) {
  const double gap = (v.back() - v.front()) / static_cast<double>(v.size() - 1);
  for (std::size_t k = 1; k < v.size(); ++k)
    if (std::abs(v[k] - v[k - 1] - gap) > 1e-6 * (v.back() - v.front())) return false;
  return true;
}

MapAxis axis_of(const Sweep& sweep) {
  MapAxis axis;
  axis.parameter = sweep.parameter;
  axis.index.resize(sweep.values.size());
  std::iota(axis.index.begin(), axis.index.end(), std::size_t{0});
  std::sort(axis.index.begin(), axis.index.end(),
            [&](std::size_t a, std::size_t b) { return sweep.values[a] < sweep.values[b]; });
  for (std::size_t k : axis.index) axis.values.push_back(sweep.values[k]);
  axis.logarithmic = axis.values.front() > 0.0 && !evenly_spaced(axis.values);
  return axis;
}

/// `theory`'s bound for `backend` at each value of the axis it does not bound, ascending;
/// empty where the map has no axis it bounds or it does not cover every value.
std::vector<BoundaryPoint> bounds(const Scene& scene, const MapTheory& theory,
                                  const std::string& backend) {
  const bool bounds_rows = scene.sweep->parameter == theory.bounded;
  if (!bounds_rows && scene.second_sweep->parameter != theory.bounded) return {};
  const MapAxis other = bounds_rows ? map_columns(scene) : map_rows(scene);
  // The bounded parameter's value at a point does not move its bound: any one will do.
  const double any = bounds_rows ? scene.sweep->values.front() : scene.second_sweep->values.front();
  std::vector<BoundaryPoint> out;
  for (double value : other.values) {
    const Scene point =
        bounds_rows ? map_point_scene(scene, any, value) : map_point_scene(scene, value, any);
    const std::optional<double> limit = theory.bound(point, backend);
    if (!limit) return {};
    out.push_back({value, *limit});
  }
  return out;
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
  const bool logarithmic = axis.logarithmic;
  const double a = logarithmic ? std::log(v[k]) : v[k];
  const double b = logarithmic ? std::log(v[k + 1]) : v[k + 1];
  const double x = logarithmic ? std::log(value) : value;
  return static_cast<double>(k) + 0.5 + (x - a) / (b - a);
}

const MapTheory* map_theory(const Scene& scene, const std::string& backend) {
  for (const MapTheory& theory : map_theories())
    if (!bounds(scene, theory, backend).empty()) return &theory;
  return nullptr;
}

std::vector<BoundaryPoint> map_boundary(const Scene& scene, const std::string& backend) {
  const MapTheory* theory = map_theory(scene, backend);
  return theory ? bounds(scene, *theory, backend) : std::vector<BoundaryPoint>{};
}

}  // namespace bb
