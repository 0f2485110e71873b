#include "metrics/errors.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "physics/energy.hpp"

namespace bb {

double ErrorMetrics::get(const std::string& name) const {
  if (name == "position_max") return position_max;
  if (name == "position_rms") return position_rms;
  if (name == "position_final") return position_final;
  if (name == "velocity_max") return velocity_max;
  if (name == "energy_max") return energy_max;
  throw std::invalid_argument("unknown error metric '" + name + "'");
}

int ErrorMetrics::worst_body() const {
  int worst = -1;
  for (std::size_t i = 0; i < bodies.size(); ++i)
    if (worst < 0 || bodies[i].position_max > bodies[static_cast<std::size_t>(worst)].position_max)
      worst = static_cast<int>(i);
  return worst;
}

ErrorMetrics compare(const Scene& scene, const Trajectory& run, const Trajectory& reference) {
  if (run.states.size() != reference.states.size())
    throw std::invalid_argument("trajectories cover different samples");
  ErrorMetrics m;
  m.bodies.resize(scene.bodies.size());
  std::vector<double> sum_squares(scene.bodies.size(), 0.0);
  EnergyMeter energy(scene);
  const double energy_scale = std::max(std::abs(energy(reference.states.front())), 1.0);
  for (std::size_t j = 0; j < run.states.size(); ++j) {
    const State& s = run.states[j];
    const State& r = reference.states[j];
    for (std::size_t i = 0; i < m.bodies.size(); ++i) {
      BodyErrors& b = m.bodies[i];
      const double dx = (s[i].position - r[i].position).norm();
      b.position_max = std::max(b.position_max, dx);
      b.velocity_max = std::max(b.velocity_max, (s[i].velocity - r[i].velocity).norm());
      sum_squares[i] += dx * dx;
      if (j + 1 == run.states.size()) b.position_final = dx;
    }
    const double de = std::abs(energy(s) - energy(r)) / energy_scale;
    m.energy_max = std::max(m.energy_max, de);
  }
  // The scene's figures are the worst body's, each on its own.
  for (std::size_t i = 0; i < m.bodies.size(); ++i) {
    BodyErrors& b = m.bodies[i];
    b.position_rms = std::sqrt(sum_squares[i] / static_cast<double>(run.states.size()));
    m.position_max = std::max(m.position_max, b.position_max);
    m.position_rms = std::max(m.position_rms, b.position_rms);
    m.position_final = std::max(m.position_final, b.position_final);
    m.velocity_max = std::max(m.velocity_max, b.velocity_max);
  }
  return m;
}

double max_position_difference(const Trajectory& a, const Trajectory& b) {
  double worst = 0.0;
  const std::size_t n = std::min(a.states.size(), b.states.size());
  for (std::size_t j = 0; j < n; ++j)
    for (std::size_t i = 0; i < a.states[j].size(); ++i)
      worst = std::max(worst, (a.states[j][i].position - b.states[j][i].position).norm());
  return worst;
}

StateDifference max_state_difference(const Trajectory& a, const Trajectory& b) {
  StateDifference d;
  const std::size_t n = std::min(a.states.size(), b.states.size());
  for (std::size_t j = 0; j < n; ++j)
    for (std::size_t i = 0; i < a.states[j].size(); ++i) {
      const BodyState &x = a.states[j][i], &y = b.states[j][i];
      d.position = std::max(d.position, (x.position - y.position).norm());
      d.velocity = std::max(d.velocity, (x.velocity - y.velocity).norm());
      // q and -q are the same turn: angularDistance takes the shorter way.
      d.orientation = std::max(d.orientation, x.orientation.angularDistance(y.orientation));
      d.spin = std::max(d.spin, (x.angular_velocity - y.angular_velocity).norm());
    }
  return d;
}

}  // namespace bb
