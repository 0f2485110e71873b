// Helpers shared by the engine adapter tests: the loaded plugins, one engine by name, and
// what a run's engine_settings say.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "run/engine_catalogue.hpp"
#include "run/registry.hpp"
#include "seam/engine_catalogue.hpp"
#include "support/missing.hpp"

namespace bb::test {

/// Every plugin next to the program, loaded once per test program.
inline const Registry& registry() {
  static const Registry r = Registry::load();
  return r;
}

/// The engine backend called `name`, or nullptr when its plugin was not built.
inline const Backend* engine(const std::string& name) {
  for (const Backend* b : registry().engines())
    if (b->name() == name) return b;
  return nullptr;
}

/// The description of the engine that provides backend `name` (nullptr for none).
inline const EngineDescription* description_of(const std::string& name) {
  for (const EngineDescription& d : engine_catalogue())
    if (find_variant(d, name) != nullptr) return &d;
  return nullptr;
}

/// "" when every engine backend of `names` was built here (a backend no engine describes,
/// the reference or a course method, is part of the program); else which were not and why, as the
/// registry says (for BB_SKIP_IF_MISSING).
inline std::string not_built(const std::vector<std::string>& names) {
  std::string out;
  for (std::size_t i = 0; i < names.size(); ++i) {
    const std::string& name = names[i];
    const bool named_before =
        std::find(names.begin(), names.begin() + i, name) != names.begin() + i;
    if (engine(name) != nullptr || named_before || description_of(name) == nullptr) continue;
    std::string why = "no plugin in " + plugin_folder();
    for (const Registry::Missing& missing : registry().missing_engines())
      if (missing.name == name) why = missing.why;
    out += (out.empty() ? "" : "; ") + name + " was not built (" + why + ")";
  }
  return out;
}

/// Every rigid-body engine backend the adapters describe, in the catalogue's order: each
/// one with an adapter that turns bodies (supports rotation) and takes part in any scene
/// (needs nothing: not an `<engine>/force` build). A new engine is tested by every test
/// that takes its engines from here, with no test file edited.
inline std::vector<std::string> rigid_engines() {
  std::vector<std::string> out;
  for (const EngineDescription& d : engine_catalogue())
    for (const EngineVariant& v : d.variants)
      if (d.has_adapter && v.needs == FeatureSet{} && v.supports.has(Feature::Rotation))
        out.push_back(v.name);
  return out;
}

/// The rigid engines that simulate `feature` (ThreeD, say), by their description.
inline std::vector<std::string> rigid_engines_with(Feature feature) {
  std::vector<std::string> out;
  for (const std::string& b : rigid_engines())
    if (description_supports(*description_of(b), b).has(feature)) out.push_back(b);
  return out;
}

/// Whether backend `name`'s description says it simulates `feature`.
inline bool described_with(const std::string& name, Feature feature) {
  const EngineDescription* d = description_of(name);
  return d != nullptr && description_supports(*d, name).has(feature);
}

/// Whether `name` is an engine backend the catalogue describes whose plugin is not here: a
/// row of it says "not built" rather than running.
inline bool described_but_not_built(const std::string& name) {
  return description_of(name) != nullptr && engine(name) == nullptr;
}

/// The engines built a second way with their springs added by hand (`<engine>/force`).
inline std::vector<std::string> engines_with_force_build() {
  std::vector<std::string> out;
  for (const std::string& b : rigid_engines()) {
    if (find_variant(*description_of(b), b + "/force") != nullptr) out.push_back(b);
  }
  return out;
}

/// Whether backend `name` computes in single precision, by its description.
inline bool single_precision(const std::string& name) {
  const EngineDescription* d = description_of(name);
  return d != nullptr && find_variant(*d, name)->single_precision;
}

/// A backend name as a test name: "bullet-float" as "bullet_float", "box2d/force" as
/// "box2d_force".
inline std::string test_name(std::string name) {
  for (char& c : name)
    if (c == '-' || c == '/' || c == '+' || c == '.') c = '_';
  return name;
}

/// Why backend `name` steps in stages, as its description says, or "" (it steps like
/// semi-implicit Euler).
inline std::string staged_step(const std::string& name) {
  const EngineDescription* d = description_of(name);
  return d == nullptr ? "" : find_variant(*d, name)->staged_step;
}

/// A parameterised test's name from its backend-name parameter (see test_name).
inline std::string param_test_name(const ::testing::TestParamInfo<std::string>& info) {
  return test_name(info.param);
}

/// Whether the backend called `name` takes part in `scene` (its needs are met there).
inline bool takes_part(const std::string& name, const Scene& scene) {
  for (const Backend* b : backends_for(scene, registry()).all)
    if (b->name() == name) return true;
  return false;
}

/// The value of setting `key`, or nullptr.
inline const SettingValue* setting(const Settings& settings, const std::string& key) {
  for (const auto& [k, v] : settings)
    if (k == key) return &v;
  return nullptr;
}

/// A text setting ("" when missing or not text).
inline std::string text_setting(const Settings& settings, const std::string& key) {
  const SettingValue* v = setting(settings, key);
  return v && std::holds_alternative<std::string>(*v) ? std::get<std::string>(*v) : "";
}

/// A number setting (NaN when missing or not a number).
inline double number_setting(const Settings& settings, const std::string& key) {
  const SettingValue* v = setting(settings, key);
  return v && std::holds_alternative<double>(*v) ? std::get<double>(*v) : std::nan("");
}

/// Any setting as text ("" when missing): numbers printed with %g, flags as true/false.
inline std::string setting_text(const Settings& settings, const std::string& key) {
  const SettingValue* v = setting(settings, key);
  if (v == nullptr) return "";
  if (const auto* text = std::get_if<std::string>(v)) return *text;
  if (const auto* flag = std::get_if<bool>(v)) return *flag ? "true" : "false";
  char number[32];
  std::snprintf(number, sizeof number, "%g", std::get<double>(*v));
  return number;
}

/// The issue's drop: a ball of radius 0.5 m and 1 kg from 10 m onto a ground with
/// restitution 0.8 (closed-form bottom apexes 6.080, 3.891, 2.490 m). Times in seconds,
/// as TOML numbers; `dts` is the TOML list's inside.
inline std::string dropped_ball(const std::string& duration, const std::string& sample,
                                const std::string& dts, const std::string& report_dt) {
  return "name = \"drop\"\ndims = 2\nduration = " + duration + "\nsample = " + sample + "\ndt = [" +
         dts + "]\nreport_dt = " + report_dt +
         "\n[ground]\nrestitution = 0.8\n[[body]]\nname = \"ball\"\nradius = 0.5\nmass = "
         "1.0\nposition = [0.0, 10.0, 0.0]\n";
}

/// Three balls in a row without gravity; "a" flies through "b" towards "c"; `pair` is the
/// one [[contact]] (e.g. ["a", "c"]), with restitution 1.
inline std::string three_in_a_row(const std::string& pair) {
  return std::string(R"(name = "row"
dims = 2
duration = 2.0
sample = 0.1
dt = [0.01]
report_dt = 0.01
gravity = [0.0, 0.0, 0.0]
[[body]]
name = "a"
radius = 0.5
mass = 1.0
position = [-2.0, 1.0, 0.0]
velocity = [2.0, 0.0, 0.0]
[[body]]
name = "b"
radius = 0.5
mass = 1.0
position = [0.0, 1.0, 0.0]
[[body]]
name = "c"
radius = 0.5
mass = 1.0
position = [0.0, 10.0, 0.0]
[[contact]]
bodies = )") +
         pair + "\nrestitution = 1.0\n";
}

}  // namespace bb::test
