// The bundled suite's claims say what the course text says, and each can fail: every quote
// is the course text's own words, the claims the text does not make are marked as the
// cases' own, and every claim, fed numbers that contradict it, gets "fails" from every
// backend it judges.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <map>

#include "run/claims.hpp"
#include "run/engine_catalogue.hpp"
#include "run/region_claims.hpp"
#include "run/sweep_runner.hpp"
#include "study/backend_names.hpp"
#include "study/metric_names.hpp"
#include "support/test_support.hpp"

#ifndef BEACHBALL_COURSE_TEXT
#define BEACHBALL_COURSE_TEXT ""
#endif

namespace bb {
namespace {

namespace fs = std::filesystem;

/// Every case of the bundled suite, in name order.
std::vector<Scene> bundled_cases() {
  std::vector<fs::path> files;
  for (const auto& entry : fs::directory_iterator(test::source_path("cases")))
    if (entry.path().extension() == ".toml") files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  std::vector<Scene> out;
  for (const fs::path& file : files) out.push_back(load_case(file.string()));
  return out;
}

/// `text` with every run of spaces, tabs and line breaks made one space, trimmed.
std::string normalised(const std::string& text) {
  std::string out;
  bool space = false;
  for (char c : text) {
    if (c == ' ' || c == '\t' || c == '\n' || c == '\r') {
      space = !out.empty();
      continue;
    }
    if (space) out += ' ';
    space = false;
    out += c;
  }
  return out;
}

/// The course text's path: $BEACHBALL_COURSE_TEXT, else the build's BEACHBALL_COURSE_TEXT
/// (cmake -DBEACHBALL_COURSE_TEXT=...); "" when neither is set. The repository holds no copy.
std::string course_text_path() {
  if (const char* env = std::getenv("BEACHBALL_COURSE_TEXT"); env != nullptr && *env != '\0')
    return env;
  return BEACHBALL_COURSE_TEXT;
}

TEST(SuiteClaims, EveryQuoteIsTheCourseTextsOwnWords) {
  const std::string path = course_text_path();
  if (path.empty())
    GTEST_SKIP() << "the course text is not in the repository: set BEACHBALL_COURSE_TEXT (or "
                    "configure with -DBEACHBALL_COURSE_TEXT=) to the path of "
                    "beachball-physics.txt to check every claim's quote against it";
  ASSERT_TRUE(fs::exists(path)) << "BEACHBALL_COURSE_TEXT names no file: " << path;
  const std::string text = normalised(test::bytes(path));
  int quotes = 0;
  for (const Scene& scene : bundled_cases())
    for (const Claim& claim : scene.claims) {
      if (claim.quote.empty()) continue;
      ++quotes;
      EXPECT_NE(text.find(normalised(claim.quote)), std::string::npos)
          << scene.file << ":" << claim.line << ": the course text has no \"" << claim.quote
          << "\"";
    }
  EXPECT_GT(quotes, 30);
}

// The sentences the text does not make are the cases' own: Sproing with 4 or 6 springs (the
// text says only "try ... and see what happens"), the falling wall that stands (the text's
// weight torque, F_g sin(phi), is zero for an upright wall), and the kinematic spin that
// matches a gripping floor.
TEST(SuiteClaims, ClaimsTheTextDoesNotMakeAreTheCasesOwn) {
  std::map<std::string, std::vector<bool>> own;  // case -> each claim's own
  for (const Scene& scene : bundled_cases())
    for (const Claim& claim : scene.claims) own[scene.name].push_back(claim.own);
  EXPECT_EQ(own["sproing_2d_4"], std::vector<bool>({true}));
  EXPECT_EQ(own["sproing_2d_6"], std::vector<bool>({true}));
  EXPECT_EQ(own["falling_wall"], std::vector<bool>({true}));
  // The rule's spin is the text's; that it matches a gripping floor is the case's.
  EXPECT_EQ(own["kinematic_rotation"], std::vector<bool>({false, true}));
}

/// Sets `metric` of `run` to `value`: an error metric, or an observable whose reference
/// value is 0 (so that its distance from the reference, compare = "error", is |value|).
void set_quantity(RunRecord& run, const std::string& metric, double value) {
  const auto& errors = error_metric_names();
  if (std::find(errors.begin(), errors.end(), metric) != errors.end()) {
    if (!run.errors) run.errors = ErrorMetrics{};
    std::map<std::string, double ErrorMetrics::*> field = {
        {"position_max", &ErrorMetrics::position_max},
        {"position_rms", &ErrorMetrics::position_rms},
        {"position_final", &ErrorMetrics::position_final},
        {"velocity_max", &ErrorMetrics::velocity_max},
        {"energy_max", &ErrorMetrics::energy_max}};
    (*run.errors).*field.at(metric) = value;
    return;
  }
  run.observables.push_back({metric, {value, ""}, 0.0});
}

/// A value of the left side that makes `left op right` false.
double contradicting(const Claim& claim, double right) {
  const double margin = 1.0 + std::abs(right) + claim.tolerance;
  const double out =
      claim.op == "<" || claim.op == "<=" || claim.op == "~" ? right + margin : right - margin;
  // A distance from the reference is never negative; 0 is below any right side >= 0.
  return claim.against_reference ? std::max(out, 0.0) : out;
}

/// Results in which `claim` must fail for `judged`: at every dt, the left side's quantity
/// for `judged` contradicts the right side's (1, or the claim's number). Empty when both
/// sides name one quantity of one backend: nothing could make such a claim fail.
std::optional<CaseResults> contradicting_results(const Scene& scene, const Claim& claim,
                                                 const std::string& judged) {
  const auto backend_of = [&](const ClaimSide& side) {
    return side.backend == "*" ? judged : side.backend;
  };
  const double right = claim.right.is_number() ? claim.right.number : 1.0;
  std::map<std::pair<std::string, std::string>, double> values;
  if (!claim.right.is_number()) values[{backend_of(claim.right), claim.right.metric}] = right;
  const auto left = std::pair{backend_of(claim.left), claim.left.metric};
  if (values.count(left)) return std::nullopt;
  values[left] = contradicting(claim, right);
  CaseResults results;
  results.scene = &scene;
  results.reference_run.backend = "reference";
  std::map<std::string, std::vector<RunRecord>> runs;
  for (const auto& [key, value] : values) {
    if (key.first == "reference") {
      set_quantity(results.reference_run, key.second, value);
      continue;
    }
    if (runs[key.first].empty())
      for (double dt : scene.dt) {
        RunRecord run;
        run.backend = key.first;
        run.dt = dt;
        runs[key.first].push_back(run);
      }
    for (RunRecord& run : runs[key.first]) set_quantity(run, key.second, value);
  }
  for (auto& [backend, list] : runs)
    results.runs.insert(results.runs.end(), list.begin(), list.end());
  return results;
}

/// A map in which `claim`, a map's claim, must fail at every point it judges: its backend's
/// outcome at each point is the other one than the claim states there (diverged for "ok", ok
/// for "exploded").
CaseResults contradicting_map(const Scene& scene, const Claim& claim) {
  CaseResults results;
  results.scene = &scene;
  results.sweep =
      SweepResults{scene.sweep->parameter, sweep_points(scene), scene.second_sweep->parameter};
  for (SweepPoint& p : results.sweep->points) p.runs.push_back(RunRecord{});
  const std::vector<RegionPoint> places = region_points(results, claim);
  for (std::size_t i = 0; i < places.size(); ++i) {
    RunRecord& run = results.sweep->points[i].runs.front();
    run.backend = claim.region->backend;
    const std::string& word =
        places[i].place == RegionPlace::Inside ? claim.region->inside : claim.region->outside;
    run.status = word == "ok" ? RunStatus::Diverged : RunStatus::Ok;
  }
  return results;
}

TEST(SuiteClaims, EveryClaimFailsOnNumbersThatContradictIt) {
  int checked = 0;
  for (const Scene& scene : bundled_cases()) {
    const std::vector<std::string> backends = backend_names(scene, engine_catalogue());
    for (std::size_t k = 0; k < scene.claims.size(); ++k) {
      const Claim& claim = scene.claims[k];
      if (claim.region) {
        const std::vector<ClaimResult> verdicts = judge_claims(contradicting_map(scene, claim));
        EXPECT_EQ(verdicts[k].verdicts.front().kind, VerdictKind::Fails)
            << scene.file << ":" << claim.line << ": " << verdicts[k].verdicts.front().verdict;
        ++checked;
        continue;
      }
      // "*": the reference and a backend that is not the reference; else the one named.
      std::vector<std::string> judged = {claim.left.backend};
      if (claim.left.backend == "*") {
        judged = {*std::find_if(backends.begin(), backends.end(),
                                [](const std::string& b) { return b != "reference"; })};
        if (judges_the_reference(claim)) judged.push_back("reference");
      }
      for (const std::string& backend : judged) {
        const std::optional<CaseResults> results = contradicting_results(scene, claim, backend);
        ASSERT_TRUE(results) << scene.file << ":" << claim.line << ": " << backend
                             << " compares a quantity with itself";
        const std::vector<ClaimResult> verdicts = judge_claims(*results);
        for (const ClaimVerdict& v : verdicts[k].verdicts) {
          if (v.backend != backend) continue;
          EXPECT_EQ(v.verdict, "fails") << scene.file << ":" << claim.line << ": " << backend;
          ++checked;
        }
      }
    }
  }
  EXPECT_GT(checked, 40);
}

}  // namespace
}  // namespace bb
