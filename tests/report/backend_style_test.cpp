// Every backend has a colour of its own, and every two backends that can share a plot are
// told apart at a glance on a projector: course/rk4 and mujoco/rk4 were two blues 4.6
// apart (CIE76), in 33 plots together.
#include "report/backend_style.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <set>
#include <string>
#include <vector>

#include "run/engine_catalogue.hpp"
#include "study/backend_names.hpp"
#include "support/test_support.hpp"

namespace bb {
namespace {

/// The smallest CIE76 distance (delta E, the Euclidean distance in CIELAB) between two
/// backends' colours on one plot. 2.3 is a just noticeable difference between two patches
/// side by side; thin lines and small markers, read from across a room on a projector's
/// washed-out colours, need an order more: 20 keeps even the closest pair (a course
/// variant's shade beside an engine) apart as two named colours, not two shades of one.
constexpr double kMinDeltaE = 20.0;
/// The lightest a line may be (L*, white is 100): lighter lines fade into a white page.
constexpr double kMaxLightness = 76.0;

struct Lab {
  double l, a, b;
};

/// "#rrggbb" (sRGB, D65) in CIELAB.
Lab lab(const std::string& hex) {
  unsigned r = 0, g = 0, b = 0;
  EXPECT_EQ(std::sscanf(hex.c_str(), "#%02x%02x%02x", &r, &g, &b), 3) << hex;
  const auto linear = [](unsigned c) {
    const double u = c / 255.0;
    return u <= 0.04045 ? u / 12.92 : std::pow((u + 0.055) / 1.055, 2.4);
  };
  const double R = linear(r), G = linear(g), B = linear(b);
  const double x = (0.4124564 * R + 0.3575761 * G + 0.1804375 * B) / 0.95047;
  const double y = 0.2126729 * R + 0.7151522 * G + 0.0721750 * B;
  const double z = (0.0193339 * R + 0.1191920 * G + 0.9503041 * B) / 1.08883;
  const auto f = [](double t) {
    return t > 216.0 / 24389.0 ? std::cbrt(t) : (24389.0 / 27.0 * t + 16.0) / 116.0;
  };
  return {116.0 * f(y) - 16.0, 500.0 * (f(x) - f(y)), 200.0 * (f(y) - f(z))};
}

double delta_e(const Lab& p, const Lab& q) {
  return std::sqrt((p.l - q.l) * (p.l - q.l) + (p.a - q.a) * (p.a - q.a) +
                   (p.b - q.b) * (p.b - q.b));
}

/// The backends of a case whose [course] is `course` (TOML lines), reference included.
std::vector<std::string> backends_of(const std::string& course) {
  const Scene scene = test::scene_from(test::minimal_case("colours") + "[course]\n" + course);
  return backend_names(scene, engine_catalogue());
}

/// Every set of backends that can share a plot, as far as the rules go: every bundled
/// case's, and a case's that compares all four integrators under every choice of one rule
/// (a case comparing two rules at once gets sums of shades, not checked here).
std::vector<std::pair<std::string, std::vector<std::string>>> plot_sets() {
  std::vector<std::pair<std::string, std::vector<std::string>>> out;
  for (const auto& entry : std::filesystem::directory_iterator(test::source_path("cases"))) {
    const Scene scene = load_case(entry.path().string());
    out.push_back({scene.name, backend_names(scene, engine_catalogue())});
  }
  for (const char* rule : {"ground = [\"reflect\", \"clamp\", \"mirror\"]\n",
                           "friction = [\"naive\", \"clamp\", \"low-speed\"]\n",
                           "hit = [\"seed-plank\", \"impulse\"]\n",
                           "spin = [\"free\", \"kinematic\", \"shared\"]\n", ""})
    out.push_back({rule, backends_of(rule)});
  return out;
}

TEST(BackendStyle, EveryBackendTheCourseAndTheEnginesNameHasANamedColour) {
  std::vector<std::string> names = {"reference"};
  for (const std::string& i : known_integrators()) names.push_back("course/" + i);
  for (const std::string& e : engine_backend_names(engine_catalogue())) names.push_back(e);
  EXPECT_TRUE(std::find(names.begin(), names.end(), "mujoco/implicit") != names.end());
  for (const std::string& name : names) {
    EXPECT_TRUE(backend_style(name).named) << name << " has only a spare colour";
    EXPECT_EQ(backend_style(name).colour, backend_style(name).colour) << name;
  }
}

// An engine's colours are in its description, in one place with the rest of what it says.
TEST(BackendStyle, AnEngineBackendsColourIsTheOneItsDescriptionGives) {
  int engines = 0;
  for (const EngineDescription& e : engine_catalogue())
    for (const EngineVariant& v : e.variants) {
      EXPECT_EQ(backend_style(v.name).colour, v.colour) << v.name;
      ++engines;
    }
  EXPECT_GT(engines, 0);
}

TEST(BackendStyle, EveryTwoBackendsThatCanShareAPlotAreFarApartInColour) {
  int pairs = 0;
  for (const auto& [what, names] : plot_sets()) {
    std::set<std::string> seen;
    for (std::size_t i = 0; i < names.size(); ++i) {
      ASSERT_TRUE(seen.insert(names[i]).second) << what << ": " << names[i] << " twice";
      const std::string a = backend_style(names[i]).colour;
      if (names[i] != "reference") {
        EXPECT_LE(lab(a).l, kMaxLightness) << what << ": " << names[i] << " " << a;
      }
      for (std::size_t j = i + 1; j < names.size(); ++j) {
        const std::string b = backend_style(names[j]).colour;
        EXPECT_GT(delta_e(lab(a), lab(b)), kMinDeltaE)
            << what << ": " << names[i] << " " << a << " and " << names[j] << " " << b;
        ++pairs;
      }
    }
  }
  EXPECT_GT(pairs, 1000);
}

TEST(BackendStyle, EveryBackendOfEveryBundledCaseHasAColourOfItsOwnInItsCase) {
  for (const auto& entry : std::filesystem::directory_iterator(test::source_path("cases"))) {
    const Scene scene = load_case(entry.path().string());
    std::set<std::string> names;
    for (const std::string& name : backend_names(scene, engine_catalogue())) names.insert(name);
    names.insert("reference");
    std::set<std::string> colours;
    for (const std::string& name : names) {
      const BackendStyle style = backend_style(name);
      EXPECT_EQ(style.colour, backend_style(name).colour);
      EXPECT_TRUE(colours.insert(style.colour).second)
          << scene.name << ": " << name << " shares " << style.colour;
    }
  }
}

}  // namespace
}  // namespace bb
