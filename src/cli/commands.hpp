// The subcommands of the `beachball` program. Each returns the process exit code.
#pragma once

#include <string>
#include <vector>

#include "report/atomic_file.hpp"
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

/// Writes <case>.json, .csv, .md and the plots into `batch` (renamed into place only when
/// the batch is committed).
void write_case_outputs(const CaseResults& results, FileBatch& batch);

/// Every check that can fail before work starts, for every scene: --dt and --backends
/// name what the case has, every output name fits; then the output folder is created (when
/// `out` is not empty), probed for writing and cleared of dead runs' temporaries.
void check_before_work(const std::vector<Scene>& scenes, const RunOptions& options,
                       const std::string& out);

int list_command(const std::vector<std::string>& paths);
int run_command(const std::vector<std::string>& paths, const std::string& out,
                const RunOptions& options);
int report_command(const std::vector<std::string>& paths, const std::string& out,
                   const RunOptions& options);
int stability_command(const std::vector<std::string>& paths, const std::string& out,
                      const RunOptions& options);
int check_command(const std::vector<std::string>& paths, const std::string& junit,
                  const RunOptions& options);

}  // namespace bb::cli
