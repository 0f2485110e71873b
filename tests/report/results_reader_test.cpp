// The results JSON read back is the rows it was written from (each value to the bit), and
// a file that is not such results is refused with the file, the line or the field, and why.
#include "report/results_reader.hpp"

#include <gtest/gtest.h>

#include "report/json_writer.hpp"
#include "study/case_error.hpp"

namespace bb {
namespace {

CaseResults written(const Scene& scene) {
  CaseResults results;
  results.scene = &scene;
  results.reference_run.backend = "reference";
  ObservableResult speed{"final_speed/ball", {9.5, ""}, 9.0 + 1.0 / 3.0};
  results.reference_run.observables.push_back(speed);
  RunRecord ok;
  ok.backend = "course/rk4";
  ok.dt = 1.0 / 60.0;
  ok.errors = ErrorMetrics{0.1 / 3.0, 2e-17, 3.0, 4.5, 1.0 / 7.0, {}};
  ok.observables.push_back(speed);
  ok.observables.push_back({"bounce_apex/ball/1", {std::nullopt, "no bounce"}, 1.25});
  RunRecord diverged;
  diverged.backend = "course/explicit-euler";
  diverged.dt = 0.1;
  diverged.status = RunStatus::Diverged;
  diverged.reason = "its energy grew past 100 times the scene's";
  results.runs = {ok, diverged};
  return results;
}

TEST(ResultsReader, ReadsBackEveryRowItWasWrittenFrom) {
  Scene scene;
  scene.name = "drop";
  const CaseResults results = written(scene);
  const KeptResults kept = read_results_json(results_json(results).dump(2), "drop.json");
  EXPECT_EQ(kept.case_name, "drop");
  ASSERT_EQ(kept.runs.size(), 3u);
  std::vector<const RunRecord*> rows = {&results.reference_run, &results.runs[0], &results.runs[1]};
  for (std::size_t k = 0; k < rows.size(); ++k) {
    const RunRecord &a = *rows[k], &b = kept.runs[k];
    EXPECT_EQ(a.backend, b.backend);
    EXPECT_EQ(a.dt, b.dt);
    EXPECT_EQ(a.status, b.status);
    EXPECT_EQ(a.reason, b.reason);
    ASSERT_EQ(a.errors.has_value(), b.errors.has_value());
    for (const char* m :
         {"position_max", "position_rms", "position_final", "velocity_max", "energy_max"})
      if (a.errors) {
        EXPECT_EQ(a.errors->get(m), b.errors->get(m)) << m;
      }
    ASSERT_EQ(a.observables.size(), b.observables.size());
    for (std::size_t o = 0; o < a.observables.size(); ++o) {
      EXPECT_EQ(a.observables[o].name, b.observables[o].name);
      EXPECT_EQ(a.observables[o].measured.value, b.observables[o].measured.value);
      EXPECT_EQ(a.observables[o].measured.note, b.observables[o].measured.note);
      EXPECT_EQ(a.observables[o].reference, b.observables[o].reference);
    }
  }
}

/// The problem reading `text` as "f.json" reports.
CaseError refusal(const std::string& text) {
  try {
    read_results_json(text, "f.json");
  } catch (const CaseError& e) {
    return e;
  }
  ADD_FAILURE() << "accepted: " << text;
  return CaseError("", 0, "");
}

TEST(ResultsReader, RefusesWhatIsNotResultsNamingTheLineOrTheField) {
  const CaseError cut = refusal("{\n  \"schema\": \"beachball-results/1\",\n  \"runs\": [\n");
  EXPECT_EQ(cut.file(), "f.json");
  EXPECT_EQ(cut.line(), 4) << cut.what();
  EXPECT_NE(cut.problem().find("is not JSON"), std::string::npos) << cut.what();
  EXPECT_NE(refusal("{\"schema\": \"other\"}").problem().find("beachball-results/1"),
            std::string::npos);
  const CaseError dt = refusal(
      R"({"schema": "beachball-results/1", "case": "c", "runs": [{"backend": "b", "dt": "x"}]})");
  EXPECT_NE(dt.problem().find("runs[0].dt is neither a number nor null"), std::string::npos)
      << dt.what();
  const CaseError status = refusal(
      R"({"schema": "beachball-results/1", "case": "c", "runs": [{"backend": "b", "dt": 0.1,
          "status": "fine", "errors": null, "observables": {}}]})");
  EXPECT_NE(status.problem().find("runs[0].status is 'fine'"), std::string::npos) << status.what();
}

}  // namespace
}  // namespace bb
