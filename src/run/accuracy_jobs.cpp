#include "run/accuracy_jobs.hpp"

#include <stdlib.h>

#include <algorithm>
#include <filesystem>
#include <memory>
#include <numeric>
#include <optional>
#include <stdexcept>
#include <system_error>

#include "files/atomic_file.hpp"
#include "files/owned_temporary.hpp"
#include "files/whole_file.hpp"
#include "model/text.hpp"
#include "run/accuracy_run.hpp"
#include "run/child_pool.hpp"
#include "run/run_summary.hpp"
#include "run/trajectory_names.hpp"
#include "run/trajectory_writer.hpp"
#include "run/wire.hpp"

namespace bb {

namespace {

/// The prefix of the scratch folders in $TMPDIR.
constexpr const char* kScratchPrefix = "beachball-scratch-";

/// A private temporary folder in $TMPDIR, created on first use (after removing what killed
/// runs left there, provably beachball's: owned_temporary.hpp) and removed with everything in
/// it when the case is done (or interrupted: the destructor runs as the exception unwinds).
class ScratchFolder {
 public:
  /// The path of a file called `name` in the folder; "" when no folder can be made.
  std::string file(const std::string& name) {
    if (!folder_) {
      std::error_code ec;
      const std::string tmp = std::filesystem::temp_directory_path(ec).string();
      if (ec) return "";
      remove_abandoned_temporaries(tmp, kScratchPrefix);
      try {
        folder_ = std::make_unique<OwnedTemporary>(tmp, kScratchPrefix);
      } catch (const WriteError&) {
        return "";
      }
    }
    return folder_->path() + "/" + name;
  }

 private:
  std::unique_ptr<OwnedTemporary> folder_;
};

/// Writes `run` whole to `path`; false (and no file) when it cannot, a full disk say.
bool write_run(const std::string& path, const RunRecord& run) {
  if (path.empty()) return false;
  try {
    write_whole_file(path, wire::encode(run));
    return true;
  } catch (const WriteError&) {
    return false;
  }
}

RunRecord read_run(const std::string& path) {
  const std::optional<std::string> bytes = read_whole_file(path);
  if (!bytes) throw std::runtime_error("cannot read the finest run " + path);
  return wire::decode_run(*bytes);
}

/// A run record from what its child process reported.
RunRecord record_from(const ChildOutcome& outcome, const std::string& backend,
                      std::optional<double> dt) {
  RunRecord run;
  if (outcome.kind == ChildOutcome::Kind::Done) {
    run = wire::decode_run(outcome.payload);
    if (ran_to_end(run.status))
      run.messages = outcome.console;
    else if (!outcome.console.empty())
      run.reason += "; it printed: " + outcome.console;
    return run;
  }
  run.backend = backend;
  run.dt = dt;
  run.status =
      outcome.kind == ChildOutcome::Kind::Timeout ? RunStatus::Timeout : RunStatus::Crashed;
  run.reason = outcome.reason;
  return run;
}

/// Whether a backend's finest run, as it came back, is what its coarser runs are measured
/// against in their children: ok and written whole for them to read (summarised).
bool measures_the_others(const RunRecord& finest) {
  return finest.status == RunStatus::Ok && finest.summarised;
}

std::string label(const std::string& backend, std::optional<double> dt) {
  return dt ? backend + " at dt " + format_dt(*dt) : backend;
}

/// The jobs' indices in the order they are handed to the pool: the smallest dt first (the
/// most steps, the longest runs), in the jobs' order among equals. The last to start are
/// the shortest, so a case's runs do not end with one core waiting on a long run the other
/// could have shared. Each run's slot stays its job's: the order changes no result.
std::vector<std::size_t> longest_first(const std::vector<AccuracyJob>& jobs) {
  std::vector<std::size_t> order(jobs.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return jobs[a].dt < jobs[b].dt; });
  return order;
}

/// What a child does with its run before sending it back (nothing: it comes back whole).
using Finish = std::function<void(RunRecord&)>;

/// The schedule of one case's accuracy runs on a pool of child processes: what each child
/// runs, what comes back into which slot, and what each run's end submits next.
class AccuracySchedule {
 public:
  AccuracySchedule(const Scene& scene, const std::vector<AccuracyJob>& jobs,
                   const RunOptions& options,
                   const std::function<void(const std::string&)>& progress)
      : scene_(scene),
        jobs_(jobs),
        options_(options),
        progress_(progress),
        pool_(options.jobs, options.isolation) {
    out_.runs.resize(jobs.size());
  }

  AccuracyRuns run(const ReferenceBackend& reference) {
    const ReferenceBackend tighter = reference.self_check();
    submit(
        reference, scene_.sample, out_.reference, std::nullopt, nullptr,
        [this] { after_reference(); }, key_of(reference, std::nullopt, "reference"), true, true);
    if (options_.reference_self_check)
      submit(tighter, scene_.sample, out_.tight, std::nullopt, nullptr, nullptr,
             key_of(tighter, std::nullopt, "self-check"), true, false);
    pool_.run();
    out_.reference.dt.reset();
    out_.tight.dt.reset();
    return std::move(out_);
  }

 private:
  /// A backend's job (not the reference) also judges the stability trial at its dt, if the
  /// stability search begins there. A run with a key is kept between invocations; with
  /// `look_up` it is taken from the kept ones when there. A run that `writes_steps` (with
  /// --trajectories) writes them from its child into its file, and so always runs.
  void submit(const Backend& b, double dt, RunRecord& slot, std::optional<double> shown_dt,
              Finish finish, std::function<void()> then, const std::string& key, bool look_up,
              bool writes_steps, const std::string& group = "") {
    const std::string what = label(b.name(), shown_dt);
    const std::string steps_file =
        writes_steps && !options_.trajectories.empty()
            ? options_.trajectories + "/" + trajectory_file_name(b.name(), shown_dt)
            : "";
    if (!steps_file.empty() && look_up && options_.cache) options_.cache->count_run();
    if (!steps_file.empty()) look_up = false;
    if (const auto kept = look_up && options_.cache ? options_.cache->find(key) : std::nullopt) {
      slot = wire::decode_run(*kept);
      slot.reused = true;
      progress_(what);
      if (then) then();
      return;
    }
    pool_.submit(
        what, child_work(b, dt, shown_dt.has_value(), std::move(finish), steps_file),
        time_limit(scene_, dt, options_.timeout),
        [this, &slot, &b, shown_dt, what, then, key, steps_file](const ChildOutcome& o) {
          slot = record_from(o, b.name(), shown_dt);
          // A trajectory that could not be written stops the command, as any
          // output does.
          if (!slot.trajectory_problem.empty())
            throw WriteError(steps_file, slot.trajectory_problem);
          if (!key.empty())
            options_.cache->keep(key, wire::encode(slot), RunCache::repeatable(slot));
          progress_(what);
          if (then) then();
        },
        0.0, group);
  }

  /// What a run's child does: the run (writing its steps to `steps_file`, if named), then
  /// `finish`, and its record encoded for the pipe.
  ChildPool::Work child_work(const Backend& b, double dt, bool judge, Finish finish,
                             const std::string& steps_file) const {
    return [&b, &scene = scene_, dt, finish = std::move(finish), judge, steps_file] {
      std::optional<TrajectoryWriter> steps;
      if (!steps_file.empty()) steps.emplace(steps_file, scene);
      RunRecord run = run_accuracy(b, scene, dt, judge, steps ? &*steps : nullptr);
      if (steps) run.trajectory_problem = steps->close();
      if (finish) finish(run);
      return wire::encode(run);
    };
  }

  std::string key_of(const Backend& b, std::optional<double> dt, const std::string& role) const {
    return options_.cache ? options_.cache->key(scene_, role, b, dt) : std::string();
  }

  /// Job i; jobs of one non-empty `group` may share a child (child_pool.hpp).
  void job(std::size_t i, Finish finish, std::function<void()> then, const std::string& key,
           bool look_up, const std::string& group = "") {
    submit(*jobs_[i].backend, jobs_[i].dt, out_.runs[i], jobs_[i].dt, std::move(finish),
           std::move(then), key, look_up, true, group);
  }

  /// A backend's jobs are adjacent, largest dt first: its last is its finest.
  bool finest_job(std::size_t i) const {
    return i + 1 == jobs_.size() || jobs_[i + 1].backend != jobs_[i].backend;
  }

  /// Once the reference is back: every job, measured against it in its child; without an ok
  /// reference, the fallback of docs/design.md.
  void after_reference() {
    if (out_.reference.status != RunStatus::Ok) {
      for (std::size_t i = 0; i < jobs_.size(); ++i)
        if (finest_job(i)) fallback_family(i);
      return;
    }
    // Every child measures its runs against the reference it inherits at fork; the runs,
    // independent of each other, may share children.
    for (std::size_t i : longest_first(jobs_))
      job(
          i, [this](RunRecord& run) { summarise_in_child(scene_, run, out_.reference); }, nullptr,
          key_of(*jobs_[i].backend, jobs_[i].dt, "accuracy"), true, "runs");
  }

  /// The keys of a backend's runs in the fallback, its finest (job i) first, then `family`'s
  /// others. A coarser run's key says what it was measured against: this selection's finest
  /// run (another selection of dts has another finest), or nothing when that one failed (it
  /// comes back whole, and the caller measures it).
  std::vector<std::string> family_keys(std::size_t i, const std::vector<std::size_t>& family,
                                       bool against_finest) const {
    std::vector<std::string> keys = {key_of(*jobs_[i].backend, jobs_[i].dt, "fallback finest")};
    const std::string role =
        against_finest ? "fallback against " + exact_number(jobs_[i].dt) : "fallback whole";
    for (std::size_t k = 1; k < family.size(); ++k)
      keys.push_back(key_of(*jobs_[family[k]].backend, jobs_[family[k]].dt, role));
    return keys;
  }

  /// The runs of `family`, all taken from the kept ones, when every one is kept (and runs
  /// that write their steps are not asked for); false when they must run.
  bool family_kept(const std::vector<std::size_t>& family, const std::vector<std::string>& keys) {
    // Runs that write their steps run again, all of them.
    const bool kept_runs_do = options_.trajectories.empty();
    if (!kept_runs_do && options_.cache) options_.cache->count_run(static_cast<int>(keys.size()));
    const auto kept =
        kept_runs_do && options_.cache ? options_.cache->find_all(keys) : std::nullopt;
    if (!kept) return false;
    for (std::size_t k = 0; k < family.size(); ++k) {
      out_.runs[family[k]] = wire::decode_run((*kept)[k]);
      out_.runs[family[k]].reused = true;
      progress_(label(jobs_[family[k]].backend->name(), jobs_[family[k]].dt));
    }
    return true;
  }

  /// the fallback of docs/design.md for the backend whose finest job is i: that run first; it
  /// writes itself whole once, for the backend's other runs to be measured against in theirs.
  void fallback_family(std::size_t i) {
    // The backend's runs, finest first, are taken from the kept ones only all together:
    // a coarser one that is not kept needs the finest run whole, so it runs again.
    std::vector<std::size_t> family = {i};
    for (std::size_t j = i; j-- > 0 && jobs_[j].backend == jobs_[i].backend;) family.push_back(j);
    const auto kept_finest =
        options_.cache ? options_.cache->peek(family_keys(i, family, true).front()) : std::nullopt;
    const std::vector<std::string> keys =
        family_keys(i, family, !kept_finest || measures_the_others(wire::decode_run(*kept_finest)));
    if (family_kept(family, keys)) return;
    const std::string file = scratch_.file("finest-" + std::to_string(i));
    // The backend's other runs read the finest from the file in their children. Where it
    // cannot be written (no room in $TMPDIR), it comes back whole instead, and so do they,
    // for the caller to measure against it: the same numbers, measured in the parent.
    const Finish finest = [&scene = scene_, file](RunRecord& run) {
      if (run.status == RunStatus::Ok && !write_run(file, run)) return;
      summarise_in_child(scene, run, run);
    };
    job(
        i, finest, [this, i, file, family] { after_finest(i, file, family); }, keys.front(), false);
  }

  /// Once a backend's finest run is back: its other runs, measured against it in their
  /// children where it is ok and written, else brought back whole.
  void after_finest(std::size_t i, const std::string& file,
                    const std::vector<std::size_t>& family) {
    const bool ok = measures_the_others(out_.runs[i]);
    const std::vector<std::string> keys = family_keys(i, family, ok);
    // Without it they come back whole, for the caller to compare with whatever finer
    // run did finish (case_runner.cpp says which dt that was), and are kept whole.
    const Finish against_finest = [&scene = scene_, file](RunRecord& run) {
      const RunRecord finest = read_run(file);
      summarise_in_child(scene, run, finest);
    };
    for (std::size_t k = 1; k < family.size(); ++k)
      job(family[k], ok ? against_finest : nullptr, nullptr, keys[k], false);
  }

  const Scene& scene_;
  const std::vector<AccuracyJob>& jobs_;
  const RunOptions& options_;
  const std::function<void(const std::string&)>& progress_;
  AccuracyRuns out_;
  ScratchFolder scratch_;
  ChildPool pool_;
};

}  // namespace

AccuracyRuns run_accuracy_jobs(const Scene& scene, const ReferenceBackend& reference,
                               const std::vector<AccuracyJob>& jobs, const RunOptions& options,
                               const std::function<void(const std::string&)>& progress) {
  return AccuracySchedule(scene, jobs, options, progress).run(reference);
}

}  // namespace bb
