// A program's trajectories as a backend (run --trajectory NAME@DT=FILE): `import/NAME`, whose
// simulation replays its file's states, so that the runner, the observers, the metrics, the
// claims and the gates treat it as any backend. It runs at its files' steps only.
#pragma once

#include <map>
#include <memory>
#include <string>
#include <vector>

#include "run/results.hpp"
#include "run/trajectory_reader.hpp"
#include "seam/backend.hpp"
#include "study/backend_names.hpp"

namespace bb {

/// What the observables that need a run's every step say for a run whose rows are at the
/// samples only.
inline constexpr const char* kSamplesOnlyNote =
    "not measured: the trajectory has rows at the samples only";

class ImportBackend : public Backend {
 public:
  /// `name` without the prefix; `runs` one per step, each read and checked.
  ImportBackend(std::string name, std::vector<ImportedTrajectory> runs);
  std::string name() const override { return kImportPrefix + name_; }
  /// Everything: a file holds whatever its program simulated.
  FeatureSet supports() const override;
  /// No library; the version is a digest of the files, so that kept results follow them.
  std::pair<std::string, std::string> library_version() const override;
  std::unique_ptr<Simulation> start_run(const World& world, const BackendSettings& settings,
                                        double dt) const override;
  /// Its steps, largest first.
  std::vector<double> dts() const;
  /// The file of step `dt` (one of dts()).
  const ImportedTrajectory& run_at(double dt) const;
  /// The program's own cost per step at `dt`, the mean of its file's `cost_ns`; none without
  /// that column (the replay's time is not the program's).
  std::optional<Cost> cost(double dt) const;
  /// Sets what `run` (one of this backend's) cannot have from its file: its cost from
  /// `cost_ns`, and, when the rows are at the samples only, every observable that needs the
  /// steps is not measured (kSamplesOnlyNote).
  void complete(const Scene& scene, RunRecord& run) const;

 private:
  std::string name_;
  std::map<double, ImportedTrajectory> runs_;
  std::string digest_;
};

/// `--trajectory NAME@DT=FILE` as given: NAME, the step and the file.
struct TrajectoryImport {
  std::string name;
  double dt = 0.0;
  std::string file;
};

/// The imported backends of `scene`, one per NAME, every file read and checked before any
/// work. Throws CaseError (exit 2) for a DT that is not one of the case's, a NAME@DT given
/// twice, and whatever read_trajectory refuses.
std::vector<std::shared_ptr<const ImportBackend>> load_imports(
    const Scene& scene, const std::vector<TrajectoryImport>& imports);

}  // namespace bb
