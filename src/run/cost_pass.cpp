#include "run/cost_pass.hpp"

#include <ctime>

#include "model/text.hpp"
#include "run/child_pool.hpp"
#include "run/cost.hpp"
#include "run/wire.hpp"

namespace bb {

namespace {

/// A cost measurement: a run's step and how many calls of step() it takes.
struct Measure {
  double dt = 0.0;
  long calls = 0;
};

/// Fills each run's cost from its timing; `measured_at` says when a kept one was timed.
void apply_timings(const std::vector<RunRecord*>& runs, const std::vector<Measure>& measures,
                   const std::vector<Timing>& timings, const std::string& measured_at) {
  for (std::size_t k = 0; k < runs.size() && k < timings.size(); ++k) {
    RunRecord& run = *runs[k];
    const Timing& t = timings[k];
    Cost c;
    c.repeats = t.repeats;
    const auto per_step = [&](double seconds) {
      return run.steps > 0 ? seconds * 1e9 / static_cast<double>(run.steps) : 0.0;
    };
    c.ns_per_step = per_step(t.median_seconds);
    c.ns_per_step_min = per_step(t.min_seconds);
    c.ns_per_step_max = per_step(t.max_seconds);
    c.seconds_per_simulated_second =
        t.median_seconds / (static_cast<double>(measures[k].calls) * measures[k].dt);
    c.measured_at = measured_at;
    run.cost = c;
  }
}

/// What a shard keeps of a measurement that crashed or timed out (its runs have no cost).
constexpr const char* kNotTimed = "not timed: the measurement did not come back";

/// What decides a batch's timings beyond the backend and the case: each run's step and
/// calls, and how the pass times them.

std::string cost_role(const std::vector<Measure>& measures, const CostOptions& cost) {
  std::string role = "cost";
  for (const Measure& m : measures)
    role += " " + exact_number(m.dt) + "x" + std::to_string(m.calls);
  return role + " " + exact_number(cost.min_seconds) + " " + std::to_string(cost.min_repeats) +
         " " + exact_number(cost.enough_seconds) + " " + exact_number(cost.max_seconds_per_repeat) +
         " " + std::to_string(cost.max_repeats) + " " + exact_number(cost.max_wall_seconds);
}

/// The time now, UTC, to the second (ISO 8601).
std::string utc_now() {
  const std::time_t now = std::time(nullptr);
  std::tm utc{};
  gmtime_r(&now, &utc);
  char text[32];
  std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%SZ", &utc);
  return text;
}

/// Queues the cost measurement of `runs`, all of `backend`, in one child of the pool (a fork
/// per backend rather than per run), filling each run's cost when it is done. A
/// measurement that crashes or times out leaves the batch's runs without a cost. A batch
/// kept from an earlier invocation is not timed again: its costs say when they were.
/// `timed_steps` gains the seconds of steps the measurement timed.
void queue_costs(ChildPool& pool, const Backend& backend, const Scene& scene,
                 std::vector<RunRecord*> runs, const RunOptions& options,
                 const std::function<void(const std::string&)>& progress, double& timed_steps) {
  std::erase_if(runs, [](const RunRecord* r) {
    return !ran_to_end(r->status) && r->status != RunStatus::Diverged;
  });
  if (runs.empty()) return;
  // The reference is stepped sample by sample; its cost per step is per internal step.
  std::vector<Measure> measures;
  const CostOptions cost = options.cost_options;
  double limit = 0.0;
  for (const RunRecord* run : runs) {
    const Measure m{run->dt ? *run->dt : scene.sample, run->dt ? run->steps : scene.sample_count()};
    measures.push_back(m);
    limit += 4.0 * time_limit(scene, m.dt, options.timeout) + 10.0 * cost.min_seconds;
  }
  const std::string key =
      options.cache ? options.cache->key(scene, cost_role(measures, cost), backend, std::nullopt)
                    : "";
  if (const auto kept = options.cache ? options.cache->find(key) : std::nullopt) {
    // A measurement that did not come back, kept by a shard for its merge: no cost.
    if (*kept != kNotTimed) {
      const std::size_t line = kept->find('\n');
      apply_timings(runs, measures, wire::decode_timings(kept->substr(line + 1)),
                    kept->substr(0, line));
    }
    for (RunRecord* run : runs) progress("cost of " + run->backend);
    return;
  }
  pool.submit(
      "cost of " + backend.name(),
      [&backend, &scene, measures, cost] {
        std::vector<Timing> timings;
        for (const Measure& m : measures)
          timings.push_back(time_steps(backend, scene, m.dt, m.calls, cost));
        return wire::encode(timings);
      },
      limit,
      [runs, measures, progress, key, &options, &timed_steps](const ChildOutcome& outcome) {
        for (RunRecord* run : runs) progress("cost of " + run->backend);
        if (outcome.kind != ChildOutcome::Kind::Done) {
          if (!key.empty()) options.cache->keep(key, kNotTimed, false);
          return;
        }
        const std::vector<Timing> timings = wire::decode_timings(outcome.payload);
        for (const Timing& t : timings) timed_steps += t.timed_seconds;
        apply_timings(runs, measures, timings, "");
        if (!key.empty()) options.cache->keep(key, utc_now() + "\n" + outcome.payload, true);
      });
}

}  // namespace

/// The cost pass, when asked for: after every accuracy run, so runs do not disturb its
/// timing; one measurement per job at once, each a single-threaded loop on its own core.
void time_costs(const Scene& scene, const ReferenceBackend& reference,
                const std::vector<AccuracyJob>& jobs, const RunOptions& options,
                const std::function<void(const std::string&)>& progress, CaseResults& out) {
  if (options.cost) {
    ChildPool pool(options.jobs, options.isolation);
    double& timed = out.time_spent.cost_steps;
    queue_costs(pool, reference, scene, {&out.reference_run}, options, progress, timed);
    // One child per backend measures all its runs, in the order of the sweep.
    for (std::size_t i = 0; i < jobs.size(); ++i) {
      if (i > 0 && jobs[i].backend == jobs[i - 1].backend) continue;
      std::vector<RunRecord*> runs;
      for (std::size_t k = i; k < jobs.size() && jobs[k].backend == jobs[i].backend; ++k)
        runs.push_back(&out.runs[k]);
      queue_costs(pool, *jobs[i].backend, scene, runs, options, progress, timed);
    }
    pool.run();
  }
}

}  // namespace bb
