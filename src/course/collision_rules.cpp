#include "course/collision_rules.hpp"

#include <stdexcept>

namespace bb::course {

GroundRule ground_rule(const std::string& name) {
  if (name == "reflect") return GroundRule::Reflect;
  if (name == "clamp") return GroundRule::Clamp;
  if (name == "mirror") return GroundRule::Mirror;
  throw std::invalid_argument("unknown ground rule '" + name + "'");
}

HitRule hit_rule(const std::string& name) {
  if (name == "seed-plank") return HitRule::SeedPlank;
  if (name == "impulse") return HitRule::Impulse;
  throw std::invalid_argument("unknown hit rule '" + name + "'");
}

std::string ground_rule_name(GroundRule rule) {
  switch (rule) {
    case GroundRule::Reflect:
      return "reflect";
    case GroundRule::Clamp:
      return "clamp";
    case GroundRule::Mirror:
      return "mirror";
  }
  return "?";
}

void resolve_fixed(GroundRule rule, const contact::Proximity& p, double restitution,
                   Eigen::Vector3d& position, Eigen::Vector3d& velocity) {
  const double normal_speed = velocity.dot(p.normal);
  velocity -= (1.0 + restitution) * normal_speed * p.normal;
  // gap < 0 is how far the body went in; clamp takes it out by that, mirror by twice that.
  if (rule == GroundRule::Clamp) position -= p.gap * p.normal;
  if (rule == GroundRule::Mirror) position -= 2.0 * p.gap * p.normal;
}

void blend_collision(double m1, double m2, double restitution, const Eigen::Vector3d& normal,
                     Eigen::Vector3d& v1, Eigen::Vector3d& v2) {
  const double e = restitution, v1b = v1.dot(normal), v2b = v2.dot(normal);
  const double v1a = (v1b * (m1 - e * m2) + (1.0 + e) * v2b * m2) / (m1 + m2);
  const double v2a = ((1.0 + e) * v1b * m1 + v2b * (m2 - e * m1)) / (m1 + m2);
  v1 += (v1a - v1b) * normal;
  v2 += (v2a - v2b) * normal;
}

}  // namespace bb::course
