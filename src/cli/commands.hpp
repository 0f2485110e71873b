// The subcommands of the `beachball` program. Each returns the process exit code.
#pragma once

#include <string>
#include <vector>

#include "files/file_batch.hpp"
#include "report/gnuplot.hpp"
#include "report/plots.hpp"
#include "run/case_runner.hpp"

namespace bb::cli {

/// Exit codes: 0 done, 1 a gate failed (check only), 2 bad input or usage.
inline constexpr int kExitOk = 0;
inline constexpr int kExitGateFailed = 1;
inline constexpr int kExitBadInput = 2;

/// Case files named on the command line (files or folders), or the bundled suite when
/// none; all loaded and validated before any work starts. Throws CaseError.
std::vector<Scene> load_cases(const std::vector<std::string>& paths);
/// The bundled suite's folder.
std::string bundled_cases_folder();

/// Writes <case>.json, .csv, .md and the plots into `batch` (moved into place only when
/// the batch is committed); returns the plots drawn.
PlotFiles write_case_outputs(const CaseResults& results, FileBatch& batch);

/// The drawings kept with the results (report/gnuplot.hpp), while it lives: reused unless
/// --fresh; none without a cache.
KeptDrawings keep_drawings(const RunOptions& options);

/// The files `run` writes for `scene`: <case>.json, .csv, .md and its plots.
std::vector<std::string> case_output_names(const Scene& scene);

/// Every check of the cases that can fail before work starts: --dt and --backends name
/// what each case has, every output name fits.
void check_before_work(const std::vector<Scene>& scenes, const RunOptions& options);

/// Says on stderr, before any work, each map's size: its points and runs on this machine
/// (run/map_budget.hpp); its time follows once its first point has run (`on_note`).
void say_map_sizes(const std::vector<Scene>& scenes, const RunOptions& options);

/// `options` with the programs' trajectories it names (`import_files`) read and checked
/// against the one case they belong to; throws CaseError with more than one case.
RunOptions with_imports(const std::vector<Scene>& scenes, const RunOptions& options);

int list_command(const std::vector<std::string>& paths);
/// `run`; with `all_runs_first` (a merge), every case's results are had before any case's
/// files are written; with `trajectories`, every run's state at every step too, into
/// <out>/<case>-trajectories/ (docs/output-files.md#trajectories).
int run_command(const std::vector<std::string>& paths, const std::string& out,
                const RunOptions& options, bool all_runs_first = false, bool trajectories = false);
int report_command(const std::vector<std::string>& paths, const std::string& out,
                   const RunOptions& options);
int stability_command(const std::vector<std::string>& paths, const std::string& out,
                      const RunOptions& options);
/// The command a shard is a share of: `run` (its accuracy and cost runs) or `report` (those,
/// the stability searches and the sweeps).
enum class ShardOf { run, report };
/// `report --shard I/N` or `run --shard I/N`: runs the shard's share of the command's work
/// (options.shard) and keeps its results in `out` (options.cache), with a manifest of what
/// it was made from.
int shard_command(const std::vector<std::string>& paths, const std::string& out,
                  const RunOptions& options, ShardOf command);
/// Puts the shards' folders together and writes, into `out`, the report or run's files
/// (whichever command the shards were made by) from their kept results; refuses
/// (CaseError) shards of other cases, another build or command, or an incomplete set.
int merge_command(const std::vector<std::string>& shards, const std::vector<std::string>& paths,
                  const std::string& out, const RunOptions& options);
/// `check`: the gates, and with `baseline` (a folder of <case>.json) each value compared
/// with its kept one; exit 1 when a gate fails or a value got worse.
int check_command(const std::vector<std::string>& paths, const std::string& junit,
                  const std::string& baseline, const RunOptions& options);

}  // namespace bb::cli
