#include <fmt/format.h>

#include "cli/commands.hpp"
#include "report/atomic_file.hpp"
#include "report/format.hpp"
#include "report/table.hpp"

namespace bb::cli {

namespace {

std::string index_page(const std::vector<CaseResults>& all) {
  Table t;
  t.headers = {"case", "title", "course section", "runs ok", "gates"};
  t.right_aligned = {false, false, false, true, false};
  for (const CaseResults& r : all) {
    int ok = 0, total = 0, passed = 0;
    for (const RunRecord& run : r.runs) {
      if (run.status == RunStatus::Unsupported) continue;
      ++total;
      ok += run.status == RunStatus::Ok;
    }
    for (const GateResult& g : r.gates) passed += g.passed;
    const std::string gates =
        r.gates.empty() ? "none" : fmt::format("{}/{} pass", passed, r.gates.size());
    t.rows.push_back({fmt::format("[{0}]({0}.md)", r.scene->name), r.scene->title,
                      r.scene->seed.empty() ? "-" : r.scene->seed, fmt::format("{}/{}", ok, total),
                      gates});
  }
  return "# beachball report\n\nThe standard suite, one page per case. Each page shows the scene, "
         "every backend's error against the reference and its cost at the game-frame step, the "
         "whole dt sweep, the gates and the engine settings used. Regenerate with the README's "
         "report command.\n\n" +
         render_markdown(t);
}

}  // namespace

int report_command(const std::vector<std::string>& paths, const std::string& out,
                   const RunOptions& options) {
  const std::vector<Scene> scenes = load_cases(paths);
  const Registry registry = Registry::load();
  std::vector<CaseResults> all;
  for (const Scene& scene : scenes) {
    fmt::print("running {} ...\n", scene.name);
    std::fflush(stdout);
    all.push_back(run_case(scene, registry, options));
  }
  // Pages are written only when every case has run.
  for (const CaseResults& r : all) write_case_outputs(r, out);
  write_file_atomically(out + "/README.md", index_page(all));
  fmt::print("written: {}/README.md and one page per case\n", out);
  return kExitOk;
}

}  // namespace bb::cli
