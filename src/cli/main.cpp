// beachball: compare the course text's methods with Bullet, Box2D, ODE and MuJoCo on the same
// scenes.
#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <thread>

#include "cli/commands.hpp"
#include "cli/option_values.hpp"
#include "files/result_cache.hpp"
#include "run/interrupt.hpp"
#include "run/outside_plugins.hpp"
#include "run/run_cache.hpp"
#include "study/case_error.hpp"

namespace {

/// What the command line says: the values of every option, filled in by CLI11.
struct Values {
  std::vector<std::string> cases;
  std::string out, backends, dts, junit, baseline;
  /// --jobs when not given: the cores, within the option's range.
  int default_jobs =
      static_cast<int>(std::clamp(static_cast<double>(std::thread::hardware_concurrency()),
                                  bb::cli::kJobsRange.min, bb::cli::kJobsRange.max));
  int jobs = default_jobs;
  bool no_cost = false;
  bool no_isolation = false;
  double timeout = 0.0;
  double cost_seconds = 0.005;
  /// $BEACHBALL_CACHE when set (a folder, or "off"), else the user's cache folder.
  std::string shard;                ///< "I/N": report, run and check
  std::vector<std::string> shards;  ///< merge's shard folders
  std::string cache =
      std::getenv("BEACHBALL_CACHE") ? std::getenv("BEACHBALL_CACHE") : bb::default_cache_folder();
  bool fresh = false;
  bool trajectories = false;         ///< run: every run's state at every step, as CSV files
  std::vector<std::string> plugins;  ///< --plugin: backend plugins built outside the tree
  /// run, report, check: programs' trajectories, NAME@DT=FILE each
  std::vector<std::string> imports;
};

/// The subcommands, once declared.
struct Commands {
  CLI::App* list;
  CLI::App* run;
  CLI::App* report;
  CLI::App* stability;
  CLI::App* check;
  CLI::App* merge;
};

/// --plugin: options of every command that runs backends, and of `list`.
void add_plugin_option(CLI::App* command, Values& v) {
  command->add_option("--plugin", v.plugins,
                      "a backend plugin built outside beachball (PATH.so, repeatable; also "
                      "every beachball-*.so in the folders of $BEACHBALL_PLUGIN_PATH)");
}

/// --jobs: how many of `what` run at once, within kJobsRange; every command that runs in
/// parallel declares it here.
void add_jobs_option(CLI::App* command, Values& v, const std::string& what) {
  const bb::cli::OptionRange& range = bb::cli::kJobsRange;
  command
      ->add_option("--jobs", v.jobs,
                   fmt::format("{} in parallel ({:g} to {:g})", what, range.min, range.max))
      ->default_val(v.default_jobs);
}

/// Options shared by the commands that run and time a sweep.
void add_sweep_options(CLI::App* command, Values& v) {
  add_jobs_option(command, v, "accuracy runs");
  command->add_flag("--no-cost", v.no_cost, "skip the timing pass");
  command
      ->add_option("--cost-time", v.cost_seconds,
                   "minimum timed seconds per run in the cost pass (0.001 to 600)")
      ->default_val(0.005);
}

/// Options of every command that runs backends.
void add_isolation_options(CLI::App* command, Values& v) {
  command->add_option("--timeout", v.timeout,
                      "seconds a run may take, 0.001 to 86400 (default: from the case's size)");
  command->add_flag(
      "--no-isolation", v.no_isolation,
      "run in this process, not in child processes (for debugging: a crash ends the program)");
}

/// Programs' trajectories as backend rows: every command that runs a case's rows.
void add_import_option(CLI::App* command, Values& v) {
  command->add_option("--trajectory", v.imports,
                      "NAME@DT=FILE: a program's trajectory of the case at step DT (as --dt "
                      "takes it) as the backend row import/NAME; repeatable, one case only");
}

/// Options of every command whose results are kept between invocations.
void add_cache_options(CLI::App* command, Values& v) {
  command->add_option("--cache", v.cache,
                      "folder of kept results, or 'off' (default: $BEACHBALL_CACHE, else "
                      "$XDG_CACHE_HOME/beachball or ~/.cache/beachball)");
  command->add_flag("--fresh", v.fresh, "run everything again (new results are still kept)");
}

/// `list`: cases, backends, and who supports what.
CLI::App* declare_list(CLI::App& app, Values& v) {
  auto* list = app.add_subcommand("list", "cases, backends, and who supports what");
  list->add_option("CASES", v.cases, "case files or folders (default: the bundled suite)");
  add_plugin_option(list, v);
  return list;
}

/// `run`: cases into <out>/<case>.json, .csv and .md.
CLI::App* declare_run(CLI::App& app, Values& v) {
  auto* run = app.add_subcommand("run", "run cases and write <out>/<case>.json, .csv and .md");
  run->add_option("CASES", v.cases, "case files or folders")->required();
  run->add_option("--out", v.out, "output folder")->default_val("out");
  run->add_option("--backends", v.backends, "comma-separated backend names (default: all)");
  run->add_option("--dt", v.dts, "comma-separated steps from the case's dt, e.g. 1/60,1/120");
  add_sweep_options(run, v);
  add_isolation_options(run, v);
  add_plugin_option(run, v);
  add_import_option(run, v);
  add_cache_options(run, v);
  auto* run_shard =
      run->add_option("--shard", v.shard,
                      "I/N: run only share I of N of the work and keep its results in --out, "
                      "for `merge` (no case files)");
  run->add_flag("--trajectories", v.trajectories,
                "also write every run's state at every step (and the reference's at its "
                "samples) into <out>/<case>-trajectories/, one CSV file per run")
      ->excludes(run_shard);
  return run;
}

/// `report`: the suite and its report pages.
CLI::App* declare_report(CLI::App& app, Values& v) {
  auto* report = app.add_subcommand("report", "run the suite and write the report pages");
  report->add_option("CASES", v.cases, "case files or folders (default: the bundled suite)");
  report->add_option("--out", v.out, "report folder")->default_val("reports");
  add_sweep_options(report, v);
  add_isolation_options(report, v);
  add_plugin_option(report, v);
  add_import_option(report, v);
  add_cache_options(report, v);
  report->add_option("--shard", v.shard,
                     "I/N: run only share I of N of the work and keep its results in --out, "
                     "for `merge` (no pages)");
  return report;
}

/// `merge`: the report (or run's files) from the shards' kept results.
CLI::App* declare_merge(CLI::App& app, Values& v) {
  auto* merge = app.add_subcommand(
      "merge",
      "write the report (or run's files) from the kept results of every `report --shard I/N` "
      "(or `run --shard I/N`)");
  merge->add_option("SHARDS", v.shards, "the shards' folders")->required();
  merge->add_option("--cases", v.cases,
                    "the case files or folders the shards ran (default: "
                    "the bundled suite)");
  merge->add_option("--out", v.out, "report folder (or run's output folder)")
      ->default_val("reports");
  add_jobs_option(merge, v, "runs");
  add_isolation_options(merge, v);
  add_plugin_option(merge, v);
  return merge;
}

/// `stability`: the largest stable step per backend.
CLI::App* declare_stability(CLI::App& app, Values& v) {
  auto* stability =
      app.add_subcommand("stability", "largest stable step per backend, by bisection");
  stability->add_option("CASES", v.cases, "case files or folders")->required();
  stability->add_option("--out", v.out, "output folder")->default_val("out/stability");
  stability->add_option("--backends", v.backends, "comma-separated backend names (default: all)");
  add_jobs_option(stability, v, "backends searched");
  add_isolation_options(stability, v);
  add_plugin_option(stability, v);
  add_import_option(stability, v);
  add_cache_options(stability, v);
  return stability;
}

/// `check`: the gates, exit 1 when any fails.
CLI::App* declare_check(CLI::App& app, Values& v) {
  auto* check = app.add_subcommand("check", "check the gates; exit 1 when any fails");
  check->add_option("CASES", v.cases, "case files or folders (default: the bundled suite)");
  check->add_option("--junit", v.junit, "also write the gate results as JUnit XML");
  check->add_option("--baseline", v.baseline,
                    "also compare every error and observable with the results kept in this "
                    "folder (<case>.json of a `run` or a report); exit 1 where one got worse");
  add_jobs_option(check, v, "runs");
  add_isolation_options(check, v);
  add_plugin_option(check, v);
  add_import_option(check, v);
  add_cache_options(check, v);
  check->add_option("--shard", v.shard,
                    "I/N: check only the gates of share I of N of the backends (a CI matrix)");
  return check;
}

/// Declares every subcommand and its options on `app`, writing into `v`, in the order the
/// help lists them.
Commands declare_commands(CLI::App& app, Values& v) {
  app.require_subcommand(1);
  CLI::App* list = declare_list(app, v);
  CLI::App* run = declare_run(app, v);
  CLI::App* report = declare_report(app, v);
  CLI::App* merge = declare_merge(app, v);
  CLI::App* stability = declare_stability(app, v);
  CLI::App* check = declare_check(app, v);
  return {list, run, report, stability, check, merge};
}

/// The run options the parsed command line gives, each checked against its range.
bb::RunOptions run_options(const CLI::App& app, Values& v) {
  // The subcommand that was parsed, to tell an option given empty from one not given.
  const CLI::App* command = app.get_subcommands().front();
  const auto given = [&](const char* option) {
    return command->get_option_no_throw(option) != nullptr && command->count(option) > 0;
  };
  bb::RunOptions options;
  if (given("--backends")) options.backends = bb::cli::split_list("--backends", v.backends);
  if (given("--dt"))
    for (const std::string& d : bb::cli::split_list("--dt", v.dts))
      options.dts.push_back(bb::cli::parse_step(d));
  if (given("--jobs")) bb::cli::check_range("--jobs", v.jobs, bb::cli::kJobsRange);
  if (given("--timeout")) bb::cli::check_range("--timeout", v.timeout, bb::cli::kTimeoutRange);
  if (given("--cost-time"))
    bb::cli::check_range("--cost-time", v.cost_seconds, bb::cli::kCostTimeRange);
  options.jobs = v.jobs;
  options.cost = !v.no_cost;
  options.cost_options.min_seconds = v.cost_seconds;
  options.isolation = !v.no_isolation;
  options.timeout = v.timeout;
  if (given("--shard")) options.shard = bb::cli::parse_shard(v.shard);
  for (const std::string& text : v.imports)
    options.import_files.push_back(bb::cli::parse_trajectory_import(text));
  // A trajectory has its own steps only: no step can be searched, no share of it split.
  if (!v.imports.empty() && std::string(command->get_name()) == "stability")
    throw bb::CaseError("--trajectory", 0,
                        "stability searches the largest stable step by running a backend at "
                        "steps of its choosing, and a trajectory file has only the step it was "
                        "written at: give it to `run`, `report` or `check`, whose rows show "
                        "whether it diverged");
  if (!v.imports.empty() && given("--shard"))
    throw bb::CaseError("--trajectory", 0,
                        "does not go with --shard: a trajectory is read, not run, and belongs to "
                        "no share of the work");
  if (given("--baseline") && v.baseline.empty())
    throw bb::CaseError("--baseline", 0,
                        "is empty; give the folder of <case>.json to compare with");
  return options;
}

/// The parsed subcommand, run.
int dispatch(const Commands& c, const Values& v, const bb::RunOptions& options) {
  if (*c.list) return bb::cli::list_command(v.cases);
  if (*c.run && options.shard)
    return bb::cli::shard_command(v.cases, v.out, options, bb::cli::ShardOf::run);
  if (*c.run) return bb::cli::run_command(v.cases, v.out, options, false, v.trajectories);
  if (*c.report && options.shard)
    return bb::cli::shard_command(v.cases, v.out, options, bb::cli::ShardOf::report);
  if (*c.report) return bb::cli::report_command(v.cases, v.out, options);
  if (*c.merge) return bb::cli::merge_command(v.shards, v.cases, v.out, options);
  if (*c.stability) return bb::cli::stability_command(v.cases, v.out, options);
  if (*c.check) return bb::cli::check_command(v.cases, v.junit, v.baseline, options);
  return bb::cli::kExitBadInput;
}

/// Says `text` on stderr, never throwing: stderr may be a pipe whose reader went away
/// (`beachball list 2>&1 | head`), and what cannot be said then is lost, not a second error
/// (a throw from a handler below aborted the program, exit 134).
void say(const std::string& text) {
  std::fputs(text.c_str(), stderr);
}

/// A signal's stop: 128 + the signal, as a shell reports it.
int interrupted(const char* what) {
  say(fmt::format("\nbeachball: {}: {}\n", bb::interrupt_description(), what));
  return 128 + bb::interrupt_signal();
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{
      "beachball: the course text's game-physics methods beside Bullet, Box2D, ODE and MuJoCo, "
      "measured against a GSL reference"};
  Values values;
  const Commands commands = declare_commands(app, values);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? bb::cli::kExitOk : bb::cli::kExitBadInput;
  }
  try {
    bb::RunOptions options = run_options(app, values);
    // The plugins from outside the tree, each checked before any case is read or run.
    bb::load_outside_plugins(values.plugins);
    // Kept results: reused where nothing that decides them changed, said at the end.
    std::optional<bb::RunCache> cache;
    // A shard of a report or run keeps its results in its own folder; a merge reads the
    // shards'.
    const bool shard_folder = options.shard && (*commands.report || *commands.run);
    if (shard_folder) {
      options.cache = &cache.emplace(values.out, values.fresh);
      // The merge must give what the report run whole gives: a crash or a timeout too.
      cache->keep_every_outcome();
    } else if (values.cache != "off" && !*commands.list && !*commands.merge) {
      cache.emplace(values.cache, values.fresh);
      // A folder that cannot be used is said, not skipped in silence.
      if (const std::string problem = cache->store().problem(); !problem.empty()) {
        say(
            fmt::format("note: no results are kept or reused: the folder of kept results {} "
                        "cannot be used: {} (--cache DIR names another; --cache off keeps "
                        "nothing without this note)\n",
                        values.cache, problem));
        cache.reset();
      } else {
        options.cache = &*cache;
      }
    }
    bb::install_interrupt_handlers();
    const int code = dispatch(commands, values, options);
    if (cache && cache->reused() + cache->ran() > 0) {
      fmt::print("kept results: {} reused, {} run, in {}{}\n", cache->reused(), cache->ran(),
                 cache->folder(), cache->reused() > 0 ? " (--fresh runs them all again)" : "");
      if (!shard_folder) cache->prune();
    }
    // What is still buffered goes out now: a reader that went away is a stop by SIGPIPE,
    // not a silent success.
    if (std::fflush(stdout) != 0 && bb::interrupt_signal() != 0)
      return interrupted("standard output's reader went away; what was printed is cut short");
    return code;
  } catch (const bb::Interrupted& e) {
    return interrupted(e.what());
  } catch (const bb::CaseError& e) {
    // A write that failed because a signal arrived (a file past `ulimit -f`) is its stop.
    if (bb::interrupt_signal() != 0) return interrupted(e.what());
    say(fmt::format("beachball: {}\n", e.what()));
    return bb::cli::kExitBadInput;
  } catch (const std::exception& e) {
    // Printing to a reader that went away fails after SIGPIPE: that is the signal's stop.
    if (bb::interrupt_signal() != 0) return interrupted(e.what());
    say(fmt::format("beachball: error: {}\n", e.what()));
    return bb::cli::kExitBadInput;
  }
}
