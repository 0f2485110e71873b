#include "model/world.hpp"

#include <cmath>
#include <numbers>
#include <tuple>

namespace bb {

int World::body_index(const std::string& body_name) const {
  for (std::size_t i = 0; i < bodies.size(); ++i)
    if (bodies[i].name == body_name) return static_cast<int>(i);
  return -1;
}

std::pair<Vec3, Vec3> wave_motion(const Waves& w, int i, double t) {
  const double x0 = w.rest_x(i);
  const double phase = w.speed * t + w.wavenumber * x0;
  return {{x0 + w.amplitude * std::cos(phase), w.level + w.amplitude * std::sin(phase), 0.0},
          {-w.amplitude * w.speed * std::sin(phase), w.amplitude * w.speed * std::cos(phase), 0.0}};
}

Body wave_point(const Waves& w, int i) {
  Body b;
  b.name = "w" + std::to_string(i);
  b.shape = Shape::Point;
  b.mass = 1.0;
  b.line = w.line;
  std::tie(b.position, b.velocity) = wave_motion(w, i, 0.0);
  return b;
}

FeatureSet World::features() const {
  FeatureSet f;
  if (dims == 3) f.add(Feature::ThreeD);
  if (gravity.norm() > 0.0) f.add(Feature::Gravity);
  bool drag = false;
  bool magnus_used = false;
  for (const Body& b : bodies) {
    if (b.fixed) continue;
    if (air && air->density > 0.0 && b.drag_coefficient > 0.0) drag = true;
    if (air && b.magnus != 0.0) magnus_used = true;
    if (b.angular_velocity.norm() > 0.0) f.add(Feature::Rotation);
    if (b.shape == Shape::Box) f.add(Feature::Boxes);
    if (b.wind_force.norm() > 0.0) f.add(Feature::Wind);
    if (b.force.norm() > 0.0 || b.torque.norm() > 0.0) f.add(Feature::AppliedForce);
    if (b.sail || b.hull) f.add(Feature::Sailing);
    // A plate is an aerodynamic force like drag, and sees the wind.
    if (b.plate) {
      f.add(Feature::Drag);
      if (air->wind.norm() > 0.0) f.add(Feature::Wind);
    }
  }
  if (drag) f.add(Feature::Drag);
  if (magnus_used) f.add(Feature::Magnus);
  if ((drag || magnus_used) && air->wind.norm() > 0.0) f.add(Feature::Wind);
  // Restitution and friction count only where something can touch.
  if (ground) {
    f.add(Feature::GroundContact);
    if (ground->restitution > 0.0) f.add(Feature::Restitution);
    if (ground->friction_static > 0.0 || ground->friction_kinetic > 0.0) f.add(Feature::Friction);
  }
  for (const Contact& c : contacts) {
    if (!c.ground) f.add(Feature::BodyContact);
    if (c.restitution > 0.0) f.add(Feature::Restitution);
    if (c.friction_static > 0.0 || c.friction_kinetic > 0.0) f.add(Feature::Friction);
  }
  if (!springs.empty()) f.add(Feature::Springs);
  if (!hinges.empty()) f.add(Feature::Hinge);
  if (!impulses.empty()) f.add(Feature::Impulse);
  if (waves) f.add(Feature::Waves);
  return f;
}

Vec3 principal_inertia(const Body& body) {
  const double m = body.mass;
  switch (body.shape) {
    case Shape::Sphere: {
      const double k = body.shell ? 2.0 / 3.0 : 2.0 / 5.0;
      const double i = k * m * body.radius * body.radius;
      return {i, i, i};
    }
    case Shape::Box: {
      // Full side lengths are twice the half extents.
      const Vec3 s = body.half_extents * 2.0;
      return {m / 12.0 * (s.y() * s.y() + s.z() * s.z()),
              m / 12.0 * (s.x() * s.x() + s.z() * s.z()),
              m / 12.0 * (s.x() * s.x() + s.y() * s.y())};
    }
    case Shape::Point:
      return {};
  }
  return {};
}

}  // namespace bb
