// Microseconds to start a run of every backend on every bundled case at its report_dt: the
// scene built into the engine (a MuJoCo model compiled, a Bullet world filled), the part of a
// run's time that is not its steps, in this process (warm: a second start) and in a fresh
// child (cold: as the harness starts each run). Measured with Google Benchmark.
#include <benchmark/benchmark.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>

#include "bundled_suite.hpp"
#include "study/start_case.hpp"

namespace {

void start_cost(benchmark::State& state, const bb::Backend* backend, const bb::Scene* scene) {
  for (auto _ : state) {
    auto sim = start_case(*backend, *scene, scene->report_dt);
    benchmark::DoNotOptimize(sim);
    // Taking the run down is part of every run's cost too.
  }
}

/// The same in a fresh child process, as the harness starts every run: the fork, the child's
/// first start (what a process does once: compiling, first allocations) and its exit.
void cold_start_cost(benchmark::State& state, const bb::Backend* backend, const bb::Scene* scene) {
  for (auto _ : state) {
    const pid_t child = fork();
    if (child == 0) {
      auto sim = start_case(*backend, *scene, scene->report_dt);
      benchmark::DoNotOptimize(sim);
      _exit(0);
    }
    int status = 0;
    waitpid(child, &status, 0);
  }
}

}  // namespace

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  bench::for_each_supported([](const bb::Scene& scene, const bb::Backend& backend) {
    benchmark::RegisterBenchmark((scene.name + "/" + backend.name()).c_str(), start_cost, &backend,
                                 &scene)
        ->Unit(benchmark::kMicrosecond);
    benchmark::RegisterBenchmark(("cold/" + scene.name + "/" + backend.name()).c_str(),
                                 cold_start_cost, &backend, &scene)
        ->Unit(benchmark::kMicrosecond)
        ->UseRealTime();
  });
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
