// Everything but cost is bit-identical between repeated runs and between --jobs 1 and 2.
#include <gtest/gtest.h>

#include "cli/commands.hpp"
#include "report/json_writer.hpp"
#include "support/test_support.hpp"

namespace bb {
namespace {

std::string results_text(const Scene& scene, const Registry& registry, int jobs) {
  RunOptions options;
  options.cost = false;
  options.jobs = jobs;
  return results_json(run_case(scene, registry, options)).dump();
}

TEST(Determinism, SameResultsTwiceAndWithOneOrTwoJobs) {
  const Registry registry = Registry::load();
  for (const Scene& scene : cli::load_cases({test::source_path("cases")})) {
    const std::string first = results_text(scene, registry, 1);
    EXPECT_EQ(first, results_text(scene, registry, 1)) << scene.name;
    EXPECT_EQ(first, results_text(scene, registry, 2)) << scene.name;
  }
}

}  // namespace
}  // namespace bb
