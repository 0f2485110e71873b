#include "report/backend_style.hpp"

#include <algorithm>
#include <cstdio>
#include <functional>
#include <utility>

namespace bb {

namespace {

/// The colours of the backends every report knows by name.
constexpr std::pair<const char*, const char*> kNamed[] = {
    {"reference", "#000000"},
    {"course/explicit-euler", "#d62728"},
    {"course/semi-implicit-euler", "#ff7f0e"},
    {"course/velocity-verlet", "#2ca02c"},
    {"course/rk4", "#1f77b4"},
    {"bullet", "#9467bd"},
    {"bullet-float", "#e377c2"},
    {"bullet/force", "#8c564b"},
    {"bullet-softbody", "#c49c94"},
    {"box2d", "#17becf"},
    {"box2d/force", "#0b6e7a"},
    {"ode", "#7f7f7f"},
    {"ode/force", "#bcbd22"},
    {"mujoco", "#393b79"},
};

/// For a name no one has listed: one of these, by a hash of the name.
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

/// A course variant's shade: the ground and friction rules each move it a fixed way.
double variant_shade(const std::string& suffix) {
  constexpr std::pair<const char*, double> kVariants[] = {
      {"+reflect", -0.35},  {"+clamp", 0.35},      {"+mirror", 0.0},  {"+naive", -0.45},
      {"+low-speed", 0.5},  {"+seed-plank", -0.3}, {"+impulse", 0.3}, {"+free", 0.0},
      {"+kinematic", -0.3}, {"+shared", 0.4}};
  double amount = 0.0;
  for (const auto& [name, move] : kVariants)
    if (suffix.find(name) != std::string::npos) amount += move;
  return std::clamp(amount, -0.6, 0.6);
}

}  // namespace

BackendStyle backend_style(const std::string& backend) {
  BackendStyle style;
  style.kind = backend == "reference"             ? LineKind::Reference
               : backend.rfind("course/", 0) == 0 ? LineKind::Course
                                                  : LineKind::Engine;
  const std::size_t plus = backend.find('+');
  const std::string base = backend.substr(0, plus);
  for (const auto& [name, colour] : kNamed)
    if (base == name) style.colour = colour;
  if (style.colour.empty())
    style.colour = kSpare[std::hash<std::string>{}(base) % (sizeof kSpare / sizeof kSpare[0])];
  if (plus != std::string::npos)
    style.colour = shade(style.colour, variant_shade(backend.substr(plus)));
  return style;
}

}  // namespace bb
