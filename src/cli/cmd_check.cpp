#include <fmt/format.h>

#include <algorithm>
#include <filesystem>

#include "cli/baseline_check.hpp"
#include "cli/commands.hpp"
#include "files/atomic_file.hpp"
#include "report/baseline_text.hpp"
#include "report/format.hpp"
#include "report/junit_writer.hpp"

namespace bb::cli {

namespace {

/// Whether any value of `all` got worse than its baseline, and whether any got better.
std::pair<bool, bool> worse_and_better(const std::vector<CaseResults>& all) {
  bool worse = false, better = false;
  for (const CaseResults& r : all)
    for (const BaselineComparison& c : r.baseline) {
      worse = worse || c.change == Change::Worse;
      better = better || c.change == Change::Better;
    }
  return {worse, better};
}

/// Each case's options as a check runs them: with no sweep or map, so that their size is no
/// reason to refuse it.
void check_options_of_a_check(const std::vector<Scene>& scenes, RunOptions options) {
  options.sweep = false;
  for (const Scene& scene : scenes) check_run_options(scene, options);
}

}  // namespace

int check_command(const std::vector<std::string>& paths, const std::string& junit,
                  const std::string& baseline, const RunOptions& given) {
  const std::vector<Scene> scenes = load_cases(paths);
  const RunOptions options = with_imports(scenes, given);
  const Registry registry = Registry::load();
  check_options_of_a_check(scenes, options);
  // The JUnit file and the baseline are checked before the runs, not found bad after them.
  if (!junit.empty()) check_output_file(junit);
  const std::map<std::string, KeptResults> kept =
      baseline.empty() ? std::map<std::string, KeptResults>{} : read_baselines(baseline, scenes);
  // Column widths from every gate of every case, known before any run.
  std::size_t case_width = 4, backend_width = 7, metric_width = 6;
  for (const Scene& scene : scenes)
    for (const Gate& g : scene.gates) {
      case_width = std::max(case_width, scene.name.size());
      backend_width = std::max(backend_width, g.backend.size());
      metric_width = std::max(metric_width, g.metric.size());
    }
  std::vector<CaseResults> all;
  bool gates_failed = false;
  int gates = 0;
  int without_baseline = 0;
  // A shard checks the gates of its own backends (those whose runs are its work), and
  // compares their rows with the baseline. The results point at their scenes: these live
  // until the JUnit file is written.
  std::vector<Scene> checked;
  std::vector<RunSelection> also;
  for (const Scene& given : scenes) {
    Scene scene = given;
    std::erase_if(scene.gates,
                  [&](const Gate& g) { return !in_shard(options.shard, given, g.backend); });
    const auto found = kept.find(given.name);
    const RunSelection selection = found == kept.end()
                                       ? RunSelection{}
                                       : baseline_selection(given, found->second, options.shard);
    if (scene.gates.empty() && !given.gates.empty() && selection.backends.empty()) continue;
    if (!baseline.empty() && found == kept.end()) {
      fmt::print("no baseline for case {} (no {}.json in {})\n", given.name, given.name, baseline);
      ++without_baseline;
    }
    checked.push_back(std::move(scene));
    also.push_back(selection);
  }
  for (std::size_t k = 0; k < checked.size(); ++k) {
    const Scene& scene = checked[k];
    all.push_back(run_gates(scene, registry, options, also[k]));
    if (all.back().gates.empty()) fmt::print("{}: no gates\n", scene.name);
    for (const GateResult& g : all.back().gates) {
      gates_failed = gates_failed || !g.passed;
      ++gates;
      const std::string said =
          g.note.empty() || g.against.empty() ? g.note + g.against : g.note + "; " + g.against;
      fmt::print("{:<4} {:<{}} {:<{}} {:<{}} {:>10} <= {:<10} {}\n", g.passed ? "ok" : "FAIL",
                 scene.name, case_width, g.gate.backend, backend_width, g.gate.metric, metric_width,
                 format_value(g.value), format_value(g.gate.max), said);
    }
    const auto found = kept.find(scene.name);
    if (found == kept.end()) continue;
    compare_case(all.back(), found->second, options.shard);
    for (const BaselineComparison& c : all.back().baseline)
      if (said_alone(c))
        fmt::print("{}: {} {}\n", change_word(c.change), scene.name, baseline_change_text(c));
  }
  // A regular file is replaced whole; a pipe or a device (/dev/stdout) is written as it is.
  std::fflush(stdout);
  if (!junit.empty()) write_output_file(junit, junit_xml(all));
  bool worse = false;
  if (!baseline.empty()) {
    const auto [any_worse, any_better] = worse_and_better(all);
    worse = any_worse;
    fmt::print("{}\n", baseline_summary(baseline, all, without_baseline));
    fmt::print("{}\n", worse        ? "worse than the baseline"
                       : any_better ? "better than the baseline where it changed, nothing worse"
                                    : "unchanged from the baseline");
  }
  fmt::print("{}\n", gates_failed ? "gates failed" : gates == 0 ? "no gates" : "all gates pass");
  return gates_failed || worse ? kExitGateFailed : kExitOk;
}

}  // namespace bb::cli
