#include <fmt/format.h>

#include <algorithm>
#include <filesystem>

#include "cli/commands.hpp"
#include "files/atomic_file.hpp"
#include "report/format.hpp"
#include "report/junit_writer.hpp"

namespace bb::cli {

int check_command(const std::vector<std::string>& paths, const std::string& junit,
                  const RunOptions& options) {
  const std::vector<Scene> scenes = load_cases(paths);
  const Registry registry = Registry::load();
  for (const Scene& scene : scenes) check_run_options(scene, options);
  // The JUnit file is checked before the runs, not found unwritable after them.
  if (!junit.empty()) check_output_file(junit);
  // Column widths from every gate of every case, known before any run.
  std::size_t case_width = 4, backend_width = 7, metric_width = 6;
  for (const Scene& scene : scenes)
    for (const Gate& g : scene.gates) {
      case_width = std::max(case_width, scene.name.size());
      backend_width = std::max(backend_width, g.backend.size());
      metric_width = std::max(metric_width, g.metric.size());
    }
  std::vector<CaseResults> all;
  bool failed = false;
  // A shard checks the gates of its own backends (those whose runs are its work). The
  // results point at their scenes: these live until the JUnit file is written.
  std::vector<Scene> checked;
  for (const Scene& given : scenes) {
    Scene scene = given;
    std::erase_if(scene.gates,
                  [&](const Gate& g) { return !in_shard(options.shard, given, g.backend); });
    if (scene.gates.empty() && !given.gates.empty()) continue;
    checked.push_back(std::move(scene));
  }
  for (const Scene& scene : checked) {
    all.push_back(run_gates(scene, registry, options));
    for (const GateResult& g : all.back().gates) {
      failed = failed || !g.passed;
      fmt::print("{:<4} {:<{}} {:<{}} {:<{}} {:>10} <= {:<10} {}\n", g.passed ? "ok" : "FAIL",
                 scene.name, case_width, g.gate.backend, backend_width, g.gate.metric, metric_width,
                 format_value(g.value), format_value(g.gate.max), g.note);
    }
  }
  // A regular file is replaced whole; a pipe or a device (/dev/stdout) is written as it is.
  std::fflush(stdout);
  if (!junit.empty()) write_output_file(junit, junit_xml(all));
  fmt::print("{}\n", failed ? "gates failed" : "all gates pass");
  return failed ? kExitGateFailed : kExitOk;
}

}  // namespace bb::cli
