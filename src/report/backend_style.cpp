#include "report/backend_style.hpp"

#include <algorithm>
#include <cstdio>
#include <functional>
#include <utility>

#include "run/engine_catalogue.hpp"
#include "study/backend_names.hpp"

namespace bb {

namespace {

/// The colours of the reference and the course integrators; an engine's backends have theirs
/// in its description (adapters/<engine>/<engine>_engine.hpp). Every two colours that can
/// share a plot (these, the engines' and the course variants' shades below) are at least 20
/// apart in CIELAB (CIE76 delta E; 2.3 is a just noticeable difference, and lines on a
/// projector need far more), and none is lighter than L* 76, so each stands out on white
/// (tests/report/backend_style_test.cpp).
constexpr std::pair<const char*, const char*> kNamed[] = {
    {kReferenceName, "#000000"},
    {"course/explicit-euler", "#d32326"},
    {"course/semi-implicit-euler", "#f37400"},
    {"course/velocity-verlet", "#2ba02c"},
    {"course/rk4", "#0b76b2"},
};

/// The colour the engine catalogue gives backend `name`, or "".
std::string engine_colour(const std::string& name) {
  for (const EngineDescription& engine : engine_catalogue())
    if (const EngineVariant* variant = find_variant(engine, name)) return variant->colour;
  return "";
}

/// For a name no one has listed (an engine added without a colour): one of these, by a
/// hash of the name.
constexpr const char* kSpare[] = {"#637939", "#8c6d31", "#843c39", "#7b4173",
                                  "#3182bd", "#e6550d", "#31a354", "#756bb1"};

/// `hex` mixed with white (amount > 0) or black (amount < 0), amount in [-1, 1].
std::string shade(const std::string& hex, double amount) {
  unsigned r = 0, g = 0, b = 0;
  std::sscanf(hex.c_str() + 1, "%02x%02x%02x", &r, &g, &b);
  const auto mix = [&](unsigned c) {
    const double v = amount >= 0 ? c + (255.0 - c) * amount : c * (1.0 + amount);
    return static_cast<unsigned>(std::clamp(v, 0.0, 255.0) + 0.5);
  };
  char out[8];
  std::snprintf(out, sizeof out, "#%02x%02x%02x", mix(r), mix(g), mix(b));
  return out;
}

/// How far a course variant's shade moves towards white (lighter) and towards black.
constexpr double kLighter = 0.37, kDarker = -0.53;

/// A course variant's shade: of the choices of each rule a case can compare, one keeps the
/// integrator's colour, one is lighter and one darker, so the three variants of one
/// integrator stay apart from each other and from every other backend's colour.
double variant_shade(const std::string& suffix) {
  constexpr std::pair<const char*, double> kVariants[] = {
      {"+reflect", kDarker},   {"+clamp", kLighter}, {"+mirror", 0.0},       {"+naive", kDarker},
      {"+low-speed", 0.0},     {"+seed-plank", 0.0}, {"+impulse", kLighter}, {"+free", 0.0},
      {"+kinematic", kDarker}, {"+shared", kLighter}};
  double amount = 0.0;
  for (const auto& [name, move] : kVariants)
    if (suffix.find(name) != std::string::npos) amount += move;
  return std::clamp(amount, -0.6, 0.6);
}

}  // namespace

BackendStyle backend_style(const std::string& backend) {
  BackendStyle style;
  style.kind = backend == kReferenceName          ? LineKind::Reference
               : backend.rfind("course/", 0) == 0 ? LineKind::Course
                                                  : LineKind::Engine;
  const std::size_t plus = backend.find('+');
  const std::string base = backend.substr(0, plus);
  for (const auto& [name, colour] : kNamed)
    if (base == name) style.colour = colour, style.named = true;
  if (style.colour.empty()) style.colour = engine_colour(base), style.named = !style.colour.empty();
  if (style.colour.empty())
    style.colour = kSpare[std::hash<std::string>{}(base) % (sizeof kSpare / sizeof kSpare[0])];
  if (plus != std::string::npos)
    style.colour = shade(style.colour, variant_shade(backend.substr(plus)));
  return style;
}

}  // namespace bb
