// beachball: compare the course text's methods with Bullet, Box2D and ODE on the same scenes.
#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <thread>

#include "cli/commands.hpp"
#include "cli/option_values.hpp"
#include "run/interrupt.hpp"
#include "scene/case_error.hpp"

int main(int argc, char** argv) {
  CLI::App app{
      "beachball: the course text's game-physics methods beside Bullet, Box2D and ODE, "
      "measured against a GSL reference"};
  app.require_subcommand(1);
  std::vector<std::string> cases;
  std::string out, backends, dts, junit;
  const int default_jobs =
      static_cast<int>(std::clamp(std::thread::hardware_concurrency(), 1u, 256u));
  int jobs = default_jobs;
  bool no_cost = false;
  bool no_isolation = false;
  double timeout = 0.0;
  double cost_seconds = 0.005;

  auto* list = app.add_subcommand("list", "cases, backends, and who supports what");
  list->add_option("CASES", cases, "case files or folders (default: the bundled suite)");

  auto* run = app.add_subcommand("run", "run cases and write <out>/<case>.json, .csv and .md");
  run->add_option("CASES", cases, "case files or folders")->required();
  run->add_option("--out", out, "output folder")->default_val("out");
  run->add_option("--backends", backends, "comma-separated backend names (default: all)");
  run->add_option("--dt", dts, "comma-separated steps from the case's dt, e.g. 1/60,1/120");
  // Options shared by the commands that run and time a sweep.
  const auto add_sweep_options = [&](CLI::App* command) {
    command->add_option("--jobs", jobs, "accuracy runs in parallel (1 to 256)")
        ->default_val(default_jobs);
    command->add_flag("--no-cost", no_cost, "skip the timing pass");
    command
        ->add_option("--cost-time", cost_seconds,
                     "minimum timed seconds per run in the cost pass (0.001 to 600)")
        ->default_val(0.005);
  };
  add_sweep_options(run);
  // Options of every command that runs backends.
  const auto add_isolation_options = [&](CLI::App* command) {
    command->add_option("--timeout", timeout,
                        "seconds a run may take, 0.001 to 86400 (default: from the case's size)");
    command->add_flag(
        "--no-isolation", no_isolation,
        "run in this process, not in child processes (for debugging: a crash ends the program)");
  };
  add_isolation_options(run);

  auto* report = app.add_subcommand("report", "run the suite and write the report pages");
  report->add_option("CASES", cases, "case files or folders (default: the bundled suite)");
  report->add_option("--out", out, "report folder")->default_val("reports");
  add_sweep_options(report);
  add_isolation_options(report);

  auto* stability =
      app.add_subcommand("stability", "largest stable step per backend, by bisection");
  stability->add_option("CASES", cases, "case files or folders")->required();
  stability->add_option("--out", out, "output folder")->default_val("out/stability");
  stability->add_option("--backends", backends, "comma-separated backend names (default: all)");
  stability->add_option("--jobs", jobs, "backends searched in parallel (1 to 256)")
      ->default_val(default_jobs);
  add_isolation_options(stability);

  auto* check = app.add_subcommand("check", "check the gates; exit 1 when any fails");
  check->add_option("CASES", cases, "case files or folders (default: the bundled suite)");
  check->add_option("--junit", junit, "also write the gate results as JUnit XML");
  check->add_option("--jobs", jobs, "runs in parallel (1 to 256)")->default_val(default_jobs);
  add_isolation_options(check);

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? bb::cli::kExitOk : bb::cli::kExitBadInput;
  }

  try {
    // The subcommand that was parsed, to tell an option given empty from one not given.
    const CLI::App* command = app.get_subcommands().front();
    const auto given = [&](const char* option) {
      return command->get_option_no_throw(option) != nullptr && command->count(option) > 0;
    };
    bb::RunOptions options;
    if (given("--backends")) options.backends = bb::cli::split_list("--backends", backends);
    if (given("--dt"))
      for (const std::string& d : bb::cli::split_list("--dt", dts))
        options.dts.push_back(bb::cli::parse_step(d));
    if (given("--jobs")) bb::cli::check_range("--jobs", jobs, bb::cli::kJobsRange);
    if (given("--timeout")) bb::cli::check_range("--timeout", timeout, bb::cli::kTimeoutRange);
    if (given("--cost-time"))
      bb::cli::check_range("--cost-time", cost_seconds, bb::cli::kCostTimeRange);
    options.jobs = jobs;
    options.cost = !no_cost;
    options.cost_options.min_seconds = cost_seconds;
    options.isolation = !no_isolation;
    options.timeout = timeout;
    bb::install_interrupt_handlers();
    if (*list) return bb::cli::list_command(cases);
    if (*run) return bb::cli::run_command(cases, out, options);
    if (*report) return bb::cli::report_command(cases, out, options);
    if (*stability) return bb::cli::stability_command(cases, out, options);
    if (*check) return bb::cli::check_command(cases, junit, options);
  } catch (const bb::Interrupted& e) {
    fmt::print(stderr, "\nbeachball: interrupted by signal {}: {}\n", bb::interrupt_signal(),
               e.what());
    return 128 + bb::interrupt_signal();
  } catch (const bb::CaseError& e) {
    fmt::print(stderr, "beachball: {}\n", e.what());
    return bb::cli::kExitBadInput;
  } catch (const std::exception& e) {
    // Printing to a reader that went away fails after SIGPIPE: that is the signal's stop.
    if (bb::interrupt_signal() != 0) {
      fmt::print(stderr, "\nbeachball: interrupted by signal {}: {}\n", bb::interrupt_signal(),
                 e.what());
      return 128 + bb::interrupt_signal();
    }
    fmt::print(stderr, "beachball: error: {}\n", e.what());
    return bb::cli::kExitBadInput;
  }
  return bb::cli::kExitBadInput;
}
