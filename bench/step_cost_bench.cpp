// Nanoseconds per step of every backend on every bundled case at its report_dt, measured
// outside the harness with Google Benchmark. The scene is built once per run; only step()
// is inside the timed loop. When a run reaches the case's duration it restarts, outside
// the timer, so every step is a step of the case.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "run/case_loading.hpp"
#include "run/registry.hpp"
#include "study/start_case.hpp"

namespace {

void step_cost(benchmark::State& state, const bb::Backend* backend, const bb::Scene* scene) {
  const double dt = scene->report_dt;
  const long steps_per_run = std::lround(scene->duration / dt);
  auto sim = start_case(*backend, *scene, dt);
  long steps = 0;
  for (auto _ : state) {
    if (steps == steps_per_run) {
      state.PauseTiming();
      sim = start_case(*backend, *scene, dt);
      steps = 0;
      state.ResumeTiming();
    }
    sim->step();
    ++steps;
  }
  state.SetItemsProcessed(state.iterations());
  state.counters["dt_s"] = dt;
}

/// Every case of the bundled suite, in name order.
std::vector<bb::Scene> bundled_cases() {
  std::vector<std::filesystem::path> files;
  for (const auto& entry : std::filesystem::directory_iterator(BEACHBALL_CASES_DIR))
    if (entry.path().extension() == ".toml") files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  std::vector<bb::Scene> scenes;
  for (const auto& f : files) scenes.push_back(bb::load_case(f.string()));
  return scenes;
}

}  // namespace

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  // The bundled suite and the engine plugins next to this program.
  static const std::vector<bb::Scene> scenes = bundled_cases();
  static const bb::Registry registry = bb::Registry::load();
  static std::vector<bb::BackendSet> sets;
  for (const bb::Scene& scene : scenes) {
    sets.push_back(bb::backends_for(scene, registry));
    for (const bb::Backend* backend : sets.back().all) {
      if (!scene.features().missing_from(backend->supports()).empty()) continue;
      benchmark::RegisterBenchmark((scene.name + "/" + backend->name()).c_str(), step_cost, backend,
                                   &scene);
    }
  }
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
