#include "physics/energy_scale.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <queue>

#include "model/motion.hpp"
#include "model/text.hpp"
#include "physics/state_forces.hpp"

namespace bb {

namespace {

/// How far a body reaches from its centre (m): a sphere's radius, a box's half diagonal.
double reach(const Body& b) {
  return b.radius + b.half_extents.norm();
}

/// The most kinetic energy (J) the case's impulses give: each impulse J on a body already
/// moving as fast as its start and the earlier impulses allow, linear and angular.
double impulse_supply(const World& scene, double gravity) {
  std::vector<double> speed(scene.bodies.size()), spin(scene.bodies.size());
  for (std::size_t i = 0; i < scene.bodies.size(); ++i)
    speed[i] = scene.bodies[i].velocity.norm(), spin[i] = scene.bodies[i].angular_velocity.norm();
  double work = 0.0;
  for (const Impulse& imp : scene.impulses) {
    const Body& b = scene.bodies[imp.body];
    const double j = imp.impulse.norm(), v = speed[imp.body] + gravity * imp.time;
    work += j * v + 0.5 * j * j / b.mass;
    speed[imp.body] += j / b.mass;
    const double moment = principal_inertia(b).minCoeff();
    if (moment <= 0.0) continue;
    const double arm = (imp.point.value_or(b.position) - b.position).norm() + reach(b);
    const double turn = arm * j;  // the angular impulse's size, N m s
    work += turn * spin[imp.body] + 0.5 * turn * turn / moment;
    spin[imp.body] += turn / moment;
  }
  return work;
}

/// Per body, the deepest it can fall (m) along gravity when the scene's motion holds
/// `energy` J: bounded by free fall over the run, a level ground, a hinge, a tether.
std::vector<double> deepest_falls(const World& scene, double duration, double energy) {
  const std::size_t n = scene.bodies.size();
  const double g = scene.gravity.norm();
  const Vec3 down = scene.gravity / g;
  std::vector<double> fall(n, 0.0);
  // Tethers: shortest chains of springs from a fixed body, each spring as long as its rest
  // length plus the stretch `energy` could give it, sqrt(2 E / k). The label of a body is
  // the lowest (along gravity) its chain lets it reach.
  std::vector<double> lowest(n, std::numeric_limits<double>::infinity());
  std::vector<std::vector<std::pair<int, double>>> links(n);
  for (const Spring& s : scene.springs) {
    if (s.stiffness <= 0.0) continue;  // a spring with no stiffness holds nothing up
    const double length = s.rest_length + std::sqrt(2.0 * energy / s.stiffness);
    links[s.body_a].push_back({s.body_b, length});
    links[s.body_b].push_back({s.body_a, length});
  }
  using Label = std::pair<double, int>;
  std::priority_queue<Label, std::vector<Label>, std::greater<>> open;
  for (std::size_t i = 0; i < n; ++i)
    if (scene.bodies[i].fixed) {
      lowest[i] = down.dot(scene.bodies[i].position);
      open.push({lowest[i], static_cast<int>(i)});
    }
  // `lowest` holds, per body, the deepest point along gravity (down . x) the chain allows;
  // the search takes the smallest first, which is the tightest bound.
  while (!open.empty()) {
    const auto [depth, i] = open.top();
    open.pop();
    if (depth > lowest[i]) continue;
    for (const auto& [j, length] : links[i])
      if (depth + length < lowest[j]) open.push({lowest[j] = depth + length, j});
  }
  for (std::size_t i = 0; i < n; ++i) {
    const Body& b = scene.bodies[i];
    if (b.fixed) continue;
    const double here = down.dot(b.position);
    const double falling = std::max(down.dot(b.velocity), 0.0);
    double deepest = falling * duration + 0.5 * g * duration * duration;
    deepest = std::min(deepest, lowest[i] - here);
    for (const Hinge& h : scene.hinges)
      if (h.body == static_cast<int>(i))
        deepest = std::min(deepest, down.dot(h.anchor) + (b.position - h.anchor).norm() - here);
    // A level ground: its normal against gravity; the centre stays above it.
    if (scene.ground && scene.ground->normal.dot(down) <= -1.0 + 1e-12) {
      const double height = scene.ground->normal.dot(b.position - scene.ground->point);
      if (height >= 0.0) deepest = std::min(deepest, height);
    }
    fall[i] = std::max(deepest, 0.0);
  }
  return fall;
}

}  // namespace

std::string EnergyScale::describe() const {
  std::string parts;
  const auto part = [&](const char* name, double joules) {
    if (joules <= 0.0) return;
    parts += (parts.empty() ? "" : ", ") + std::string(name) + " " + significant_digits(joules, 3) +
             " J";
  };
  part("kinetic at the start", kinetic);
  part("gravity's fall", gravity);
  part("forces", forces);
  part("impulses", impulses);
  part("rest", rest);
  return significant_digits(total(), 3) + " J (" + parts + ")";
}

EnergyScale energy_scale(const World& scene, double duration) {
  EnergyScale scale;
  const State start = initial_state(scene);
  StateForces forces(scene);
  scale.forces = forces.model().supply(forces.view(start), duration);
  const double g = scene.gravity.norm();
  for (std::size_t i = 0; i < scene.bodies.size(); ++i) {
    const Body& b = scene.bodies[i];
    if (b.fixed) continue;
    scale.kinetic += kinetic_energy(b, start[i]);
    const double size = reach(b);
    scale.rest += b.mass * (g * size + 0.5 * (size / duration) * (size / duration));
  }
  scale.impulses = impulse_supply(scene, g);
  if (g == 0.0) return scale;
  // Gravity's release and the springs' stretch depend on each other: the least energy E
  // with E = others + release(E) (release grows like sqrt(E), so iterating from below
  // converges to it).
  const double others = scale.total();
  double energy = others;
  for (int iteration = 0; iteration < 200; ++iteration) {
    const std::vector<double> fall = deepest_falls(scene, duration, energy);
    double release = 0.0;
    for (std::size_t i = 0; i < fall.size(); ++i)
      if (!scene.bodies[i].fixed) release += scene.bodies[i].mass * g * fall[i];
    const double next = others + release;
    scale.gravity = release;
    if (std::abs(next - energy) <= 1e-9 * next) break;
    energy = next;
  }
  return scale;
}

std::vector<double> speed_bounds(const World& scene, const EnergyScale& scale, double duration) {
  std::vector<double> speed(scene.bodies.size(), 0.0);
  const double g = scene.gravity.norm();
  for (std::size_t i = 0; i < scene.bodies.size(); ++i) {
    const Body& b = scene.bodies[i];
    if (b.fixed) continue;
    speed[i] = b.velocity.norm() + g * duration + std::sqrt(2.0 * scale.total() / b.mass);
  }
  return speed;
}

}  // namespace bb
