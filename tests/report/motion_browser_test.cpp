// The motion view plays in a real browser: headless Chromium shows it at two moments, and
// the pixels differ where the bodies moved and nowhere else; rsvg-convert renders the still.
// (The plots' pictures: plot_pictures_test.cpp.)
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "support/missing.hpp"
#include "support/picture_support.hpp"
#include "support/program.hpp"
#include "support/test_support.hpp"

namespace bb {
namespace {

namespace fs = std::filesystem;
using test::Image;
using test::read_png;

/// Pixels that differ between `a` and `b` inside [x0, x1) x [y0, y1).
int differing(const Image& a, const Image& b, int x0, int y0, int x1, int y1) {
  int n = 0;
  for (int y = y0; y < y1 && y < a.height && y < b.height; ++y)
    for (int x = x0; x < x1 && x < a.width && x < b.width; ++x)
      for (int c = 0; c < 3; ++c)
        if (a.at(x, y)[c] != b.at(x, y)[c]) {
          ++n;
          break;
        }
  return n;
}

std::string chromium() {
  for (const char* path : {"/usr/bin/chromium", "/usr/bin/chromium-browser"})
    if (fs::exists(path)) return path;
  return "";
}

/// A screenshot of `svg` after `ms` milliseconds of the page's (virtual) time.
Image screenshot(const std::string& browser, const std::string& svg, int ms,
                 const std::string& png) {
  const std::string profile = png + ".profile";
  const std::string command =
      browser +
      " --headless --no-sandbox --disable-gpu --disable-quic --no-first-run "
      "--disable-background-networking --disable-component-update --disable-sync "
      "--hide-scrollbars --window-size=1090,560 --user-data-dir=" +
      profile + " --virtual-time-budget=" + std::to_string(ms) + " --screenshot=" + png +
      " file://" + svg + " > " + png + ".log 2>&1";
  EXPECT_EQ(std::system(command.c_str()), 0) << test::bytes(png + ".log");
  return read_png(png);
}

const char* kBounce = R"(name = "bounce"
title = "A ball bounces beside a wall"
dims = 2
duration = 2.0
sample = 0.02
dt = [0.02, 0.01]
report_dt = 0.01
[ground]
restitution = 0.8
[[body]]
name = "ball"
radius = 0.5
mass = 1.0
position = [0.0, 4.0, 0.0]
[[body]]
name = "wall"
shape = "box"
half_extents = [0.2, 2.0, 0.5]
position = [3.0, 2.0, 0.0]
fixed = true
)";

TEST(MotionBrowser, TheViewMovesInChromiumWhereTheBallIsAndNowhereElse) {
  const std::string browser = chromium();
  BB_SKIP_IF_MISSING(
      browser.empty() ? "Chromium is not installed (scripts/setup --tests installs it)" : "");
  BB_SKIP_IF_MISSING(test::why_no_pictures());
  const std::string dir = test::fresh_dir("motion_browser");
  const std::string path = test::write_case(dir, "bounce.toml", kBounce);
  const test::Outcome o = test::beachball(
      "run " + path + " --no-cost --backends reference,course/semi-implicit-euler --out " + dir +
      "/out");
  ASSERT_EQ(o.exit_code, 0) << o.out;
  const std::string svg = fs::absolute(dir + "/out/bounce-motion.svg").string();
  ASSERT_TRUE(fs::exists(svg));
  // The loop lasts 2 s: a moment while the ball falls, and one near its first bounce.
  const Image early = screenshot(browser, svg, 150, dir + "/early.png");
  const Image later = screenshot(browser, svg, 850, dir + "/later.png");
  ASSERT_GT(early.width, 0);
  ASSERT_EQ(early.width, later.width);
  // The scene (left of the legend) changed where the ball moved ...
  EXPECT_GT(differing(early, later, 10, 40, 770, 400), 500);
  // ... and the legend did not.
  EXPECT_EQ(differing(early, later, 790, 40, 1090, 120), 0);
}

TEST(MotionBrowser, RsvgRendersTheStill) {
  BB_SKIP_IF_MISSING(test::why_no_pictures());
  const std::string dir = test::fresh_dir("motion_still");
  const std::string path = test::write_case(dir, "bounce.toml", kBounce);
  ASSERT_EQ(test::beachball("run " + path + " --no-cost --backends reference --out " + dir + "/out")
                .exit_code,
            0);
  const std::string png = dir + "/still.png";
  ASSERT_EQ(std::system(("rsvg-convert " + dir + "/out/bounce-motion-still.svg -o " + png).c_str()),
            0);
  const Image still = read_png(png);
  ASSERT_GT(still.width, 0);
  // The four panels each show the ball: grey pixels of its fill in each quarter.
  int grey_quarters = 0;
  for (int qx = 0; qx < 2; ++qx)
    for (int qy = 0; qy < 2; ++qy) {
      bool grey = false;
      for (int y = 40 + qy * (still.height - 40) / 2;
           y < 40 + (qy + 1) * (still.height - 40) / 2 && !grey; ++y)
        for (int x = 10 + qx * 380; x < 10 + (qx + 1) * 380 && x < still.width && !grey; ++x) {
          const unsigned char* p = still.at(x, y);
          grey = p[0] == p[1] && p[1] == p[2] && p[0] > 190 && p[0] < 220;
        }
      grey_quarters += grey;
    }
  EXPECT_EQ(grey_quarters, 4);
}

}  // namespace
}  // namespace bb
