#include "run/accuracy_jobs.hpp"

#include <stdlib.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <system_error>

#include "run/accuracy_run.hpp"
#include "run/child_pool.hpp"
#include "run/run_summary.hpp"
#include "run/wire.hpp"
#include "scene/text.hpp"

namespace bb {

namespace {

/// A private temporary folder, created on first use and removed with everything in it
/// when the case is done (or interrupted: the destructor runs as the exception unwinds).
class ScratchFolder {
 public:
  ScratchFolder() = default;
  ScratchFolder(const ScratchFolder&) = delete;
  ScratchFolder& operator=(const ScratchFolder&) = delete;
  ~ScratchFolder() {
    std::error_code ignored;
    if (!path_.empty()) std::filesystem::remove_all(path_, ignored);
  }
  /// The path of a file called `name` in the folder.
  std::string file(const std::string& name) {
    if (path_.empty()) {
      std::string pattern = (std::filesystem::temp_directory_path() / "beachball-XXXXXX").string();
      if (mkdtemp(pattern.data()) == nullptr)
        throw std::runtime_error("cannot create a temporary folder in " +
                                 std::filesystem::temp_directory_path().string());
      path_ = pattern;
    }
    return path_ + "/" + name;
  }

 private:
  std::string path_;
};

void write_run(const std::string& path, const RunRecord& run) {
  std::ofstream out(path, std::ios::binary);
  const std::string bytes = wire::encode(run);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  if (!out.flush()) throw std::runtime_error("cannot write the finest run to " + path);
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
    if (run.status == RunStatus::Ok)
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
  const auto submit = [&](const Backend& b, double dt, RunRecord& slot,
                          std::optional<double> shown_dt, Finish finish,
                          std::function<void()> then) {
    const std::string what = label(b.name(), shown_dt);
    pool.submit(
        what,
        [&b, &scene, dt, finish] {
          RunRecord run = run_accuracy(b, scene, dt);
          if (finish) finish(run);
          return wire::encode(run);
        },
        time_limit(scene, dt, options.timeout),
        [&slot, &b, shown_dt, what, &progress, then](const ChildOutcome& o) {
          slot = record_from(o, b.name(), shown_dt);
          progress(what);
          if (then) then();
        });
  };
  const auto job = [&](std::size_t i, Finish finish, std::function<void()> then) {
    submit(*jobs[i].backend, jobs[i].dt, out.runs[i], jobs[i].dt, std::move(finish),
           std::move(then));
  };
  // A backend's jobs are adjacent, largest dt first: its last is its finest.
  const auto finest_job = [&](std::size_t i) {
    return i + 1 == jobs.size() || jobs[i + 1].backend != jobs[i].backend;
  };

  submit(reference, scene.sample, out.reference, std::nullopt, nullptr, [&] {
    if (out.reference.status == RunStatus::Ok) {
      // Every child measures its run against the reference it inherits at fork.
      for (std::size_t i = 0; i < jobs.size(); ++i)
        job(
            i, [&](RunRecord& run) { summarise_in_child(scene, run, out.reference); }, nullptr);
      return;
    }
    // DESIGN.md's fallback: each backend's finest run first; it writes itself whole once.
    for (std::size_t i = 0; i < jobs.size(); ++i) {
      if (!finest_job(i)) continue;
      const std::string file = scratch.file("finest-" + std::to_string(i));
      const Finish finest = [&scene, file](RunRecord& run) {
        if (run.status == RunStatus::Ok) write_run(file, run);
        summarise_in_child(scene, run, run);
      };
      job(i, finest, [&, i, file] {
        const bool ok = out.runs[i].status == RunStatus::Ok;
        // The backend's other runs read it in their children; without it they come back
        // whole, for the caller to compare with whatever finer run did finish.
        const Finish against_finest = [&scene, file](RunRecord& run) {
          const RunRecord finest = read_run(file);
          summarise_in_child(scene, run, finest);
        };
        for (std::size_t j = i; j-- > 0 && jobs[j].backend == jobs[i].backend;)
          job(j, ok ? against_finest : nullptr, nullptr);
      });
    }
  });
  submit(tighter, scene.sample, out.tight, std::nullopt, nullptr, nullptr);
  pool.run();
  out.reference.dt.reset();
  out.tight.dt.reset();
  return out;
}

}  // namespace bb
