#include "scene/backend_names.hpp"

#include "scene/engine_catalogue.hpp"

namespace bb {

const std::vector<std::string>& known_integrators() {
  static const std::vector<std::string> v = {"explicit-euler", "semi-implicit-euler",
                                             "velocity-verlet", "rk4"};
  return v;
}

const std::vector<std::string>& known_ground_rules() {
  static const std::vector<std::string> v = {"reflect", "clamp", "mirror"};
  return v;
}

const std::vector<std::string>& known_friction_rules() {
  static const std::vector<std::string> v = {"naive", "clamp", "low-speed"};
  return v;
}

std::vector<std::string> engine_backend_names() {
  std::vector<std::string> out;
  for (const EngineDescription& e : engine_catalogue())
    for (const std::string& b : e.backends) out.push_back(b);
  return out;
}

std::vector<CourseVariant> course_variants(const Scene& scene) {
  const CourseOptions& c = scene.course;
  std::vector<CourseVariant> out;
  for (const std::string& integrator : c.integrators)
    for (const std::string& ground : c.ground)
      for (const std::string& friction : c.friction) {
        std::string name = "course/" + integrator;
        // A variant's name carries a rule only when the case compares several.
        if (c.ground.size() > 1) name += "+" + ground;
        if (c.friction.size() > 1) name += "+" + friction;
        out.push_back({name, integrator, ground, friction});
      }
  return out;
}

std::vector<std::string> backend_names(const Scene& scene) {
  std::vector<std::string> out = {"reference"};
  for (const CourseVariant& v : course_variants(scene)) out.push_back(v.name);
  for (const std::string& e : engine_backend_names()) out.push_back(e);
  return out;
}

}  // namespace bb
