#include "run/claim_causes.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace bb {

namespace {

/// The number the engine recorded under `key` in its settings, if any.
std::optional<double> setting_number(const Settings& settings, const std::string& key) {
  for (const auto& [name, value] : settings)
    if (name == key)
      if (const double* number = std::get_if<double>(&value)) return *number;
  return std::nullopt;
}

bool has_setting(const Settings& settings, const std::string& key) {
  return std::any_of(settings.begin(), settings.end(),
                     [&](const auto& s) { return s.first == key; });
}

double degrees(double radians) {
  return radians * 180.0 / std::numbers::pi;
}

/// An engine given one friction coefficient (engine_friction.hpp) on a slope steeper than
/// atan of it but below atan(mu_s).
std::string one_friction_coefficient(const Scene& scene, const RunRecord& run) {
  if (!scene.ground || !has_setting(run.engine_settings, "friction_rule")) return "";
  const std::optional<double> given = setting_number(run.engine_settings, "ground_friction_max");
  const double mu_s = scene.ground->friction_static;
  const double g = scene.gravity.norm();
  if (!given || g <= 0.0 || *given >= mu_s) return "";
  const double slope =
      std::acos(std::clamp(-scene.gravity.dot(scene.ground->normal) / g, -1.0, 1.0));
  const double engine_holds = std::atan(*given), coulomb_holds = std::atan(mu_s);
  if (slope <= engine_holds || slope > coulomb_holds) return "";
  return fmt::format(
      "{} has one friction coefficient for sticking and sliding and is given mu_k = {:g}: it "
      "holds a body at rest only on slopes below atan(mu_k) = {:.2f} degrees, and this ground "
      "slopes at {:.2f} degrees (Coulomb's mu_s = {:g} holds it up to {:.2f})",
      run.backend, *given, degrees(engine_holds), degrees(slope), mu_s, degrees(coulomb_holds));
}

}  // namespace

std::string known_cause(const Scene& scene, const RunRecord& run) {
  return one_friction_coefficient(scene, run);
}

}  // namespace bb
