#include "course/friction_rules.hpp"

#include <algorithm>
#include <stdexcept>

namespace bb::course {

FrictionRule friction_rule(const std::string& name) {
  if (name == "naive") return FrictionRule::Naive;
  if (name == "clamp") return FrictionRule::Clamp;
  if (name == "low-speed") return FrictionRule::LowSpeed;
  throw std::invalid_argument("unknown friction rule '" + name + "'");
}

std::string friction_rule_name(FrictionRule rule) {
  switch (rule) {
    case FrictionRule::Naive:
      return "naive";
    case FrictionRule::Clamp:
      return "clamp";
    case FrictionRule::LowSpeed:
      return "low-speed";
  }
  return "?";
}

Eigen::Vector3d with_friction(FrictionRule rule, const Coulomb& c, const Eigen::Vector3d& n,
                              const Eigen::Vector3d& v, const Eigen::Vector3d& a, double dt) {
  const double normal = a.dot(n);
  const double press = -normal;  // N / m
  if (press <= 0.0) return a;
  const Eigen::Vector3d slide = tangential(v, n);
  const double speed = slide.norm();
  if (speed > kRestSpeed) {
    double kinetic = c.mu_kinetic * press;
    // The seed's second fix: never more than what brings the body to rest in one step.
    if (rule == FrictionRule::LowSpeed) kinetic = std::min(kinetic, speed / dt);
    return a - kinetic * (slide / speed);
  }
  const Eigen::Vector3d push = a - normal * n;
  const double pushed = push.norm();
  // Held: the ground takes the whole tangential force, which leaves the normal part only.
  if (pushed <= c.mu_static * press) return normal * n;
  return a - c.mu_kinetic * press * (push / pushed);
}

bool stops_within(const Coulomb& c, const Eigen::Vector3d& n, const Eigen::Vector3d& v,
                  const Eigen::Vector3d& a, double dt) {
  const double press = -a.dot(n);
  const Eigen::Vector3d slide = tangential(v, n);
  const double speed = slide.norm();
  if (press <= 0.0 || speed <= kRestSpeed) return false;
  const double slowing = c.mu_kinetic * press - a.dot(slide / speed);
  return speed <= slowing * dt;
}

void clamp_reversal(FrictionRule rule, const Eigen::Vector3d& n, const Eigen::Vector3d& before,
                    Eigen::Vector3d& v) {
  if (rule != FrictionRule::Clamp) return;
  const Eigen::Vector3d slide = tangential(v, n);
  if (slide.dot(tangential(before, n)) < 0.0) v -= slide;
}

}  // namespace bb::course
