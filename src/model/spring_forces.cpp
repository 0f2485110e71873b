#include "model/spring_forces.hpp"

namespace bb {

SpringNetwork spring_network(const World& scene) {
  SpringNetwork s;
  for (auto* v : {&s.a, &s.b}) v->reserve(scene.springs.size());
  for (auto* v : {&s.stiffness, &s.damping, &s.rest_length}) v->reserve(scene.springs.size());
  for (const Spring& spring : scene.springs) {
    s.a.push_back(spring.body_a);
    s.b.push_back(spring.body_b);
    s.stiffness.push_back(spring.stiffness);
    s.damping.push_back(spring.damping);
    s.rest_length.push_back(spring.rest_length);
  }
  return s;
}

}  // namespace bb
