// A map's claim's picture as a reader sees it, rendered by rsvg-convert: its verdict, a bold
// line under the legend, ends inside the picture, however long the claim's sentence and the
// verdict's list of points not judged (the tunnelling map's claims run to 150 characters).
#include "report/map_claim_picture.hpp"

#include <gtest/gtest.h>

#include "run/claims.hpp"
#include "run/sweep_runner.hpp"
#include "support/missing.hpp"
#include "support/picture_support.hpp"
#include "support/program.hpp"
#include "support/spring_map_case.hpp"
#include "support/test_support.hpp"

namespace bb {
namespace {

TEST(MapClaimPicture, ALongVerdictEndsInsideThePicture) {
  BB_SKIP_IF_MISSING(test::why_no_pictures());
  const Scene scene =
      test::scene_from(test::spring_map_case("long_verdict", "[2.0, 50.0]", "[0.1, 0.04]",
                                             R"(["semi-implicit-euler"])") +
                       R"([[claim]]
text = "Semi-implicit Euler stays ok wherever the step is below the line and explodes wherever it is above"
own = true
region = "theory"
backend = "course/semi-implicit-euler"
)");
  // The map with no run at any point: its verdict says so, point by point, at length.
  CaseResults results;
  results.scene = &scene;
  results.sweep = SweepResults{scene.sweep->parameter, sweep_points(scene), "dt"};
  results.claims = judge_claims(results);
  const std::string verdict =
      scene.claims.front().text + ": " + results.claims.front().verdicts.front().verdict;
  ASSERT_GT(verdict.size(), 150u) << verdict;
  const std::string dir = test::fresh_dir("map_claim_picture");
  test::write_case(dir, "claim.svg", map_claim_svg(results, results.claims.front()));
  ASSERT_EQ(std::system(("rsvg-convert " + dir + "/claim.svg -o " + dir + "/claim.png").c_str()),
            0);
  const test::Image picture = test::read_png(dir + "/claim.png");
  ASSERT_GT(picture.width, 0);
  // The verdict is the picture's last line: no dark pixel in its last 8 columns, the margin
  // the line keeps on its left (12 px) less a little.
  int dark = 0;
  for (int y = picture.height - 30; y < picture.height; ++y)
    for (int x = picture.width - 8; x < picture.width; ++x)
      dark += picture.at(x, y)[0] < 128 && picture.at(x, y)[3] > 128;
  EXPECT_EQ(dark, 0) << "the verdict runs off the picture's right edge: " << verdict;
}

}  // namespace
}  // namespace bb
