// Nanoseconds per step of every backend on every bundled case at its report_dt, measured
// outside the harness with Google Benchmark. The scene is built once per run; only step()
// is inside the timed loop. When a run reaches the case's duration it restarts, outside
// the timer, so every step is a step of the case.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "bundled_suite.hpp"
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

}  // namespace

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  bench::for_each_supported([](const bb::Scene& scene, const bb::Backend& backend) {
    benchmark::RegisterBenchmark((scene.name + "/" + backend.name()).c_str(), step_cost, &backend,
                                 &scene);
  });
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
