// The names of the per-step trajectory files `run --trajectories` writes
// (docs/output-files.md#trajectories): one folder per case, one file per run, each named so
// that a user can guess it from the run's row in the table.
#pragma once

#include <optional>
#include <string>

#include "study/scene.hpp"

namespace bb {

/// The case's trajectories folder inside the output folder: "<case>-trajectories".
std::string trajectory_folder_name(const std::string& case_name);

/// The file of one run: "reference.csv" for the reference (no dt); else the backend's name
/// and its step as the table shows it, each '/' written '-', joined by '@':
/// "course-semi-implicit-euler+reflect@1-60.csv".
std::string trajectory_file_name(const std::string& backend, std::optional<double> dt);

/// Throws CaseError (exit 2) when two steps of the case's sweep would give the same file
/// name (steps alike in their first 6 significant digits): checked before any work.
void check_trajectory_names(const Scene& scene);

}  // namespace bb
