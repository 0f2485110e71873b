#include "study/backend_names.hpp"

#include <algorithm>

#include "model/text.hpp"
#include "seam/engine_catalogue.hpp"

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

const std::vector<std::string>& known_hit_rules() {
  static const std::vector<std::string> v = {"seed-plank", "impulse"};
  return v;
}

const std::vector<std::string>& known_spin_rules() {
  static const std::vector<std::string> v = {"free", "kinematic", "shared"};
  return v;
}

std::vector<std::string> engine_backend_names(const EngineCatalogue& catalogue) {
  std::vector<std::string> out;
  for (const EngineDescription& e : catalogue)
    for (const EngineVariant& v : e.variants) out.push_back(v.name);
  return out;
}

std::vector<CourseVariant> course_variants(const Scene& scene) {
  const CourseOptions& c = scene.course;
  // Each phase's choices, in the order a variant's name lists them.
  const std::vector<std::pair<const std::vector<std::string>*, std::string CourseVariant::*>>
      phases = {{&c.integrators, &CourseVariant::integrator},
                {&c.ground, &CourseVariant::ground},
                {&c.friction, &CourseVariant::friction},
                {&c.hit, &CourseVariant::hit},
                {&c.spin, &CourseVariant::spin}};
  std::vector<CourseVariant> out = {{"course", "", "", "", "", ""}};
  for (const auto& [choices, field] : phases) {
    std::vector<CourseVariant> grown;
    for (const CourseVariant& v : out)
      for (const std::string& choice : *choices) {
        CourseVariant w = v;
        w.*field = choice;
        // The integrator always names the variant; a rule only when the case compares several.
        if (field == &CourseVariant::integrator)
          w.name += "/" + choice;
        else if (choices->size() > 1)
          w.name += "+" + choice;
        grown.push_back(std::move(w));
      }
    out = std::move(grown);
  }
  return out;
}

std::vector<std::string> backend_names(const Scene& scene, const EngineCatalogue& catalogue) {
  std::vector<std::string> out = {kReferenceName};
  for (const CourseVariant& v : course_variants(scene)) out.push_back(v.name);
  for (const std::string& e : engine_backend_names(catalogue)) out.push_back(e);
  return out;
}

}  // namespace bb

namespace bb {

std::string why_backend_cannot_run(const Scene& scene, const std::string& name,
                                   const EngineCatalogue& catalogue) {
  for (const EngineDescription& e : catalogue) {
    const EngineVariant* variant = find_variant(e, name);
    if (variant == nullptr) continue;
    if (!e.has_adapter) return "it has no adapter in this version of beachball";
    const FeatureSet used = scene.features();
    std::vector<std::string> absent;
    for (Feature f : variant->needs.missing_from(used)) absent.push_back(feature_name(f));
    if (!absent.empty())
      return "it takes part only in scenes with " + joined(absent) + ", and this case has none";
    std::vector<std::string> unsupported;
    for (Feature f : used.missing_from(variant->supports)) unsupported.push_back(feature_name(f));
    if (!unsupported.empty()) return "it does not support " + joined(unsupported);
    return "";
  }
  // A kinematic surface is moved by its formula, which the reference evaluates.
  if (name.rfind("course/", 0) == 0 && scene.features().has(Feature::Waves))
    return "it does not support waves (" + feature_absence_note(Feature::Waves) + ")";
  // The reference and the course variants run every other scene.
  return "";
}

std::vector<std::string> runnable_backend_names(const Scene& scene,
                                                const EngineCatalogue& catalogue) {
  std::vector<std::string> out;
  for (const std::string& name : backend_names(scene, catalogue))
    if (why_backend_cannot_run(scene, name, catalogue).empty()) out.push_back(name);
  return out;
}

}  // namespace bb
