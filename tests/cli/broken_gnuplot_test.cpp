// A gnuplot that fails, is killed or cuts its SVG short is an error, not a note: the report
// exits 2 naming the plot and what went wrong, and the previous report stays byte for byte.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <filesystem>
#include <fstream>

#include "support/program.hpp"
#include "support/test_support.hpp"

namespace bb {
namespace {

namespace fs = std::filesystem;

/// A folder holding a `gnuplot` that answers --version and then, on a script, runs `act`
/// (with $out the SVG the script asks for).
std::string fake_gnuplot(const std::string& name, const std::string& act) {
  const std::string dir = test::fresh_dir(name);
  const std::string program =
      test::write_case(dir, "gnuplot",
                       "#!/bin/sh\n"
                       "[ \"$1\" = --version ] && { echo 'gnuplot 5.4 (fake)'; exit 0; }\n"
                       "out=$(sed -n 's/^set output \"\\(.*\\)\"$/\\1/p' \"$1\")\n" +
                           act + "\n");
  chmod(program.c_str(), 0755);
  return dir;
}

/// A good report, then one with the `gnuplot` of folder `fake` first on PATH: it must exit
/// 2 naming the first plot and `reason`, and leave the good report as it was. (Each test
/// has folders of its own: ctest runs tests in parallel.)
void expect_refused_and_kept(const std::string& fake, const std::string& reason) {
  const std::string dir = fake + "_report";
  fs::remove_all(dir);
  const std::string kept = test::write_case(dir, "kept.toml", test::minimal_case("kept"));
  const std::string report = "report " + kept + " --no-cost --out " + dir + "/out";
  const test::Outcome good = test::beachball(report);
  ASSERT_EQ(good.exit_code, 0) << good.out;
  const auto before = test::snapshot(dir + "/out");
  const test::Outcome o = test::beachball(report, "export PATH=" + fake + ":$PATH;");
  EXPECT_EQ(o.exit_code, 2) << o.out;
  EXPECT_NE(o.out.find("kept-work-precision-position_max.svg"), std::string::npos) << o.out;
  EXPECT_NE(o.out.find(reason), std::string::npos) << o.out;
  EXPECT_EQ(test::snapshot(dir + "/out"), before) << "the previous report changed";
  EXPECT_EQ(test::temporaries_in(dir), "");
  EXPECT_EQ(test::temporaries_in(dir + "/out"), "");
}

TEST(BrokenGnuplot, AFailingGnuplotIsAnErrorWithWhatItSaid) {
  expect_refused_and_kept(
      fake_gnuplot("gnuplot_exits_1", "echo 'fake gnuplot: cannot draw' >&2; exit 1"),
      "gnuplot failed (exit 1): fake gnuplot: cannot draw");
}

TEST(BrokenGnuplot, AKilledGnuplotIsAnError) {
  expect_refused_and_kept(fake_gnuplot("gnuplot_killed", "kill -9 $$"),
                          "gnuplot failed (killed by signal 9)");
}

TEST(BrokenGnuplot, ACutOffSvgIsAnError) {
  expect_refused_and_kept(
      fake_gnuplot("gnuplot_cuts_svg", "printf '<?xml version=\"1.0\"?>\\n<svg><g>' > \"$out\""),
      "gnuplot left an incomplete SVG");
}

/// The note a report's page gives for its plots when `path` is the whole PATH the program
/// sees (beachball itself needs none).
std::string plots_note_with_path(const std::string& name, const std::string& path) {
  const std::string dir = test::fresh_dir(name);
  const std::string kept = test::write_case(dir, "kept.toml", test::minimal_case("kept"));
  const test::Outcome o = test::beachball(
      "run " + kept + " --no-cost --cache off --backends reference --out " + dir + "/out",
      "export PATH=" + path + ";");
  EXPECT_EQ(o.exit_code, 0) << o.out;
  const std::string page = test::bytes(dir + "/out/kept.md");
  const std::size_t at = page.find("plots skipped");
  return at == std::string::npos ? "" : page.substr(at, page.find('\n', at) - at);
}

// A gnuplot that is there but cannot start (a library missing: the loader's exit 127) is
// named as such, with what it said; only a gnuplot that is nowhere is "not found". The page
// said "not found (install gnuplot-nox)" for both.
TEST(BrokenGnuplot, AGnuplotThatFailsToStartIsNotCalledMissing) {
  const std::string dir = test::fresh_dir("gnuplot_will_not_start");
  const std::string program = test::write_case(
      dir, "gnuplot",
      "#!/bin/sh\necho 'gnuplot: error while loading shared libraries: libwx.so' >&2\nexit 127\n");
  chmod(program.c_str(), 0755);
  const std::string failing = plots_note_with_path("gnuplot_will_not_start_report", dir);
  EXPECT_NE(failing.find("gnuplot failed to start (gnuplot --version: exit 127): gnuplot: error "
                         "while loading shared libraries: libwx.so"),
            std::string::npos)
      << failing;
  EXPECT_EQ(failing.find("not found"), std::string::npos) << failing;
  const std::string missing =
      plots_note_with_path("gnuplot_nowhere_report", test::fresh_dir("gnuplot_nowhere"));
  EXPECT_NE(missing.find("gnuplot was not found (install gnuplot-nox)"), std::string::npos)
      << missing;
}

}  // namespace
}  // namespace bb
