#include "report/map_cells.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "model/text.hpp"

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

std::string map_bound_text(const MapTheory& theory, double limit) {
  return short_number(limit) + (theory.bounded == "dt" ? " s" : "");
}

}  // namespace bb
