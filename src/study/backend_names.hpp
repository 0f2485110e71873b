// The names backends go by for a given case, derived from its [course] section.
#pragma once

#include <string>
#include <vector>

#include "seam/engine_catalogue.hpp"
#include "study/scene.hpp"

namespace bb {

/// A course backend: an integrator, a floor rule, a friction rule, a rule for a ball hitting
/// a moving box and a spin rule (seed sections 1, 3, 6 and 5).
struct CourseVariant {
  std::string name;        ///< "course/semi-implicit-euler", maybe with "+reflect" etc.
  std::string integrator;  ///< "explicit-euler" | "semi-implicit-euler" | "velocity-verlet" | "rk4"
  std::string ground;      ///< "reflect" | "clamp" | "mirror"
  std::string friction;    ///< "naive" | "clamp" | "low-speed"
  std::string hit = "seed-plank";  ///< "seed-plank" | "impulse"
  std::string spin = "free";       ///< "free" | "kinematic" | "shared"
};

const std::vector<std::string>& known_integrators();
const std::vector<std::string>& known_ground_rules();
const std::vector<std::string>& known_friction_rules();
const std::vector<std::string>& known_hit_rules();
const std::vector<std::string>& known_spin_rules();
/// The engines' backend names, whether built or not, from the engines' descriptions.
std::vector<std::string> engine_backend_names(const EngineCatalogue& catalogue);

/// Every course variant the case asks for, in a stable order.
std::vector<CourseVariant> course_variants(const Scene& scene);
/// Every backend name the case could be asked to run: reference, course variants, engines
/// (those without an adapter, or that cannot run the scene, among them: asked for by name,
/// they get a row that says why).
std::vector<std::string> backend_names(const Scene& scene, const EngineCatalogue& catalogue);

/// Why backend `name` cannot run `scene` ("it does not support 3d", "it takes part only in
/// scenes with springs, and this case has none", "it has no adapter in this version of
/// beachball"), from the engines' descriptions; "" when it can. The reference and the course
/// variants run every scene.
std::string why_backend_cannot_run(const Scene& scene, const std::string& name,
                                   const EngineCatalogue& catalogue);

/// The reference's backend name: the row every other is measured against.
inline constexpr const char* kReferenceName = "reference";

/// The prefix of a program's trajectory brought in as a backend (run --trajectory
/// NAME@DT=FILE): "import/NAME".
inline constexpr const char* kImportPrefix = "import/";

/// Whether `backend` names a program's trajectory ("import/NAME"): a case's gates and claims
/// may name one, given on the command line.
inline bool is_import_name(const std::string& backend) {
  return backend.size() > std::string(kImportPrefix).size() && backend.rfind(kImportPrefix, 0) == 0;
}

/// The backends of backend_names() that run `scene`, in the same order.
std::vector<std::string> runnable_backend_names(const Scene& scene,
                                                const EngineCatalogue& catalogue);

}  // namespace bb
