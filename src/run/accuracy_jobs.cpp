#include "run/accuracy_jobs.hpp"

#include <stdlib.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <memory>
#include <stdexcept>
#include <system_error>

#include "files/atomic_file.hpp"
#include "files/owned_temporary.hpp"
#include "run/accuracy_run.hpp"
#include "run/child_pool.hpp"
#include "run/run_summary.hpp"
#include "run/trajectory_names.hpp"
#include "run/trajectory_writer.hpp"
#include "run/wire.hpp"
#include "scene/text.hpp"

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
  std::ifstream in(path, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (!in.good() && !in.eof()) throw std::runtime_error("cannot read the finest run " + path);
  return wire::decode_run(bytes);
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

}  // namespace

AccuracyRuns run_accuracy_jobs(const Scene& scene, const ReferenceBackend& reference,
                               const std::vector<AccuracyJob>& jobs, const RunOptions& options,
                               const std::function<void(const std::string&)>& progress) {
  AccuracyRuns out;
  out.runs.resize(jobs.size());
  const ReferenceBackend tighter = reference.self_check();
  ScratchFolder scratch;
  ChildPool pool(options.jobs, options.isolation);
  // What a child does with its run before sending it back (nothing: it comes back whole).
  using Finish = std::function<void(RunRecord&)>;
  // A backend's job (not the reference) also judges the stability trial at its dt, if the
  // stability search begins there. A run with a key is kept between invocations; with
  // `look_up` it is taken from the kept ones when there. A run that `writes_steps` (with
  // --trajectories) writes them from its child into its file, and so always runs.
  const auto submit = [&](const Backend& b, double dt, RunRecord& slot,
                          std::optional<double> shown_dt, Finish finish, std::function<void()> then,
                          const std::string& key, bool look_up, bool writes_steps) {
    const std::string what = label(b.name(), shown_dt);
    const bool judge = shown_dt.has_value();
    const std::string steps_file =
        writes_steps && !options.trajectories.empty()
            ? options.trajectories + "/" + trajectory_file_name(b.name(), shown_dt)
            : "";
    if (!steps_file.empty() && look_up && options.cache) options.cache->count_run();
    if (!steps_file.empty()) look_up = false;
    if (const auto kept = look_up && options.cache ? options.cache->find(key) : std::nullopt) {
      slot = wire::decode_run(*kept);
      slot.reused = true;
      progress(what);
      if (then) then();
      return;
    }
    pool.submit(
        what,
        [&b, &scene, dt, finish, judge, steps_file] {
          std::optional<TrajectoryWriter> steps;
          if (!steps_file.empty()) steps.emplace(steps_file, scene);
          RunRecord run = run_accuracy(b, scene, dt, judge, steps ? &*steps : nullptr);
          if (steps) run.trajectory_problem = steps->close();
          if (finish) finish(run);
          return wire::encode(run);
        },
        time_limit(scene, dt, options.timeout),
        [&slot, &b, shown_dt, what, &progress, then, key, &options,
         steps_file](const ChildOutcome& o) {
          slot = record_from(o, b.name(), shown_dt);
          // A trajectory that could not be written stops the command, as any output does.
          if (!slot.trajectory_problem.empty())
            throw WriteError(steps_file, slot.trajectory_problem);
          if (!key.empty())
            options.cache->keep(key, wire::encode(slot), RunCache::repeatable(slot));
          progress(what);
          if (then) then();
        });
  };
  const auto key_of = [&](const Backend& b, std::optional<double> dt, const std::string& role) {
    return options.cache ? options.cache->key(scene, role, b, dt) : std::string();
  };
  const auto job = [&](std::size_t i, Finish finish, std::function<void()> then,
                       const std::string& key, bool look_up) {
    submit(*jobs[i].backend, jobs[i].dt, out.runs[i], jobs[i].dt, std::move(finish),
           std::move(then), key, look_up, true);
  };
  // A backend's jobs are adjacent, largest dt first: its last is its finest.
  const auto finest_job = [&](std::size_t i) {
    return i + 1 == jobs.size() || jobs[i + 1].backend != jobs[i].backend;
  };

  const std::string reference_key = key_of(reference, std::nullopt, "reference");
  submit(
      reference, scene.sample, out.reference, std::nullopt, nullptr,
      [&] {
        if (out.reference.status == RunStatus::Ok) {
          // Every child measures its run against the reference it inherits at fork.
          for (std::size_t i = 0; i < jobs.size(); ++i)
            job(
                i, [&](RunRecord& run) { summarise_in_child(scene, run, out.reference); }, nullptr,
                key_of(*jobs[i].backend, jobs[i].dt, "accuracy"), true);
          return;
        }
        // the fallback of docs/design.md: each backend's finest run first; it writes itself whole once.
        for (std::size_t i = 0; i < jobs.size(); ++i) {
          if (!finest_job(i)) continue;
          // The backend's runs, finest first, are taken from the kept ones only all together:
          // a coarser one that is not kept needs the finest run whole, so it runs again.
          std::vector<std::size_t> family = {i};
          for (std::size_t j = i; j-- > 0 && jobs[j].backend == jobs[i].backend;)
            family.push_back(j);
          // A coarser run's key says what it was measured against: this selection's finest run
          // (another selection of dts has another finest), or nothing when that one failed
          // (it comes back whole, and the caller measures it).
          const auto family_keys = [&, i, family](bool against_finest) {
            std::vector<std::string> keys = {
                key_of(*jobs[i].backend, jobs[i].dt, "fallback finest")};
            const std::string role =
                against_finest ? "fallback against " + exact_number(jobs[i].dt) : "fallback whole";
            for (std::size_t k = 1; k < family.size(); ++k)
              keys.push_back(key_of(*jobs[family[k]].backend, jobs[family[k]].dt, role));
            return keys;
          };
          const auto kept_finest =
              options.cache ? options.cache->peek(family_keys(true).front()) : std::nullopt;
          const std::vector<std::string> keys =
              family_keys(!kept_finest || measures_the_others(wire::decode_run(*kept_finest)));
          // Runs that write their steps run again, all of them.
          const bool kept_runs_do = options.trajectories.empty();
          if (!kept_runs_do && options.cache)
            options.cache->count_run(static_cast<int>(keys.size()));
          if (const auto kept =
                  kept_runs_do && options.cache ? options.cache->find_all(keys) : std::nullopt) {
            for (std::size_t k = 0; k < family.size(); ++k) {
              out.runs[family[k]] = wire::decode_run((*kept)[k]);
              out.runs[family[k]].reused = true;
              progress(label(jobs[family[k]].backend->name(), jobs[family[k]].dt));
            }
            continue;
          }
          const std::string file = scratch.file("finest-" + std::to_string(i));
          // The backend's other runs read the finest from the file in their children. Where it
          // cannot be written (no room in $TMPDIR), it comes back whole instead, and so do they,
          // for the caller to measure against it: the same numbers, measured in the parent.
          const Finish finest = [&scene, file](RunRecord& run) {
            if (run.status == RunStatus::Ok && !write_run(file, run)) return;
            summarise_in_child(scene, run, run);
          };
          job(
              i, finest,
              [&, i, file, family, family_keys] {
                const bool ok = measures_the_others(out.runs[i]);
                const std::vector<std::string> keys = family_keys(ok);
                // Without it they come back whole, for the caller to compare with whatever finer
                // run did finish (case_runner.cpp says which dt that was), and are kept whole.
                const Finish against_finest = [&scene, file](RunRecord& run) {
                  const RunRecord finest = read_run(file);
                  summarise_in_child(scene, run, finest);
                };
                for (std::size_t k = 1; k < family.size(); ++k)
                  job(family[k], ok ? against_finest : nullptr, nullptr, keys[k], false);
              },
              keys.front(), false);
        }
      },
      reference_key, true, true);
  submit(tighter, scene.sample, out.tight, std::nullopt, nullptr, nullptr,
         key_of(tighter, std::nullopt, "self-check"), true, false);
  pool.run();
  out.reference.dt.reset();
  out.tight.dt.reset();
  return out;
}

}  // namespace bb
