// Nanoseconds per spring per step of every backend on spring grids ("Sproing", seed
// section 7), built through the case loader: 2D sheets with 8 neighbours from 10 x 10 to
// 300 x 300 and 3D blocks with 26 neighbours up to 30 x 30 x 30. items_per_second is
// spring updates per second. Only step() is timed; the grid restarts outside the timer.
// On the 300 x 300 sheet an engine's step takes up to 1.7 s: filter, e.g.
// --benchmark_filter='^(10x10|100x100)/'.
#include <benchmark/benchmark.h>

#include <string>
#include <vector>

#include "run/case_loading.hpp"
#include "run/registry.hpp"
#include "study/start_case.hpp"

namespace {

/// A grid case: no gravity, a kicked corner, one sample (nothing kept but the end).
std::string grid_case(int dims, int n) {
  const std::string size = dims == 2 ? "[" + std::to_string(n) + ", " + std::to_string(n) + "]"
                                     : "[" + std::to_string(n) + ", " + std::to_string(n) + ", " +
                                           std::to_string(n) + "]";
  return "name = \"grid\"\ndims = " + std::to_string(dims) +
         "\nduration = 1.0\nsample = 1.0\ndt = [0.0166666666666666667]\n"
         "gravity = [0.0, 0.0, 0.0]\n[grid]\nsize = " +
         size + "\nspacing = 0.5\nmass = 0.1\nneighbours = " + (dims == 2 ? "8" : "26") +
         "\nstiffness = 50.0\ndamping = 0.2\njitter = 0.01\n"
         "[[impulse]]\nbody = \"" +
         (dims == 2 ? "p0_0" : "p0_0_0") + "\"\ntime = 0.0\nimpulse = [-0.1, 0.2, 0.0]\n" +
         "[course]\nintegrators = [\"explicit-euler\", \"semi-implicit-euler\", "
         "\"velocity-verlet\", \"rk4\"]\n"
         // ODE's dWorldStep factors one dense matrix over every joint row: on a grid its
         // users take the iterative step, as sproing_3d does.
         "[engines.ode]\nquick_step = true\n";
}

void step_cost(benchmark::State& state, const bb::Backend* backend, const bb::Scene* scene) {
  const double dt = scene->report_dt;
  auto sim = start_case(*backend, *scene, dt);
  long steps = 0;
  for (auto _ : state) {
    // A whole second of the case, then a fresh start outside the timer.
    if (steps == 60) {
      state.PauseTiming();
      sim = start_case(*backend, *scene, dt);
      steps = 0;
      state.ResumeTiming();
    }
    sim->step();
    ++steps;
  }
  const double springs = static_cast<double>(scene->springs.size());
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * springs));
  state.counters["springs"] = springs;
  state.counters["ns_per_spring"] = benchmark::Counter(
      springs, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

}  // namespace

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  static const bb::Registry registry = bb::Registry::load();
  static std::vector<bb::Scene> scenes;
  static std::vector<bb::BackendSet> sets;
  scenes.reserve(8);
  for (const auto& [dims, n] : std::vector<std::pair<int, int>>{
           {2, 10}, {2, 30}, {2, 100}, {2, 300}, {3, 5}, {3, 10}, {3, 20}, {3, 30}})
    scenes.push_back(bb::parse_case(grid_case(dims, n), "grid.toml"));
  for (const bb::Scene& scene : scenes) {
    sets.push_back(bb::backends_for(scene, registry));
    const std::string grid = std::to_string(scene.grid->size[0]) +
                             (scene.dims == 2 ? "x" + std::to_string(scene.grid->size[1]) : "^3");
    for (const bb::Backend* backend : sets.back().all) {
      if (!scene.features().missing_from(backend->supports()).empty()) continue;
      benchmark::RegisterBenchmark((grid + "/" + backend->name()).c_str(), step_cost, backend,
                                   &scene)
          ->Unit(benchmark::kMicrosecond);
    }
  }
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
