// Where a command's outputs go, checked before any work starts: the folder can be written,
// every output name fits, and the temporaries a killed run left behind are cleared. A
// report folder is replaced as a whole: the new report is built in a sibling folder and
// exchanged with the old one in one rename, so a kill at any moment leaves one or the other.
#pragma once

#include <string>
#include <vector>

#include "scene/scene.hpp"

namespace bb::cli {

/// Removes `*.tmp.<pid>` files in `folder` and `<folder>.tmp.<pid>` folders beside it whose
/// process is gone.
void remove_stale_temporaries(const std::string& folder);

/// Throws CaseError (exit 2) naming the case file and its `name` line when an output file
/// of `scene` would have a name longer than the file system allows.
void check_output_names(const Scene& scene);

/// Throws CaseError with the OS's reason when `folder` cannot be created or written.
void check_writable(const std::string& folder);

/// A report folder rebuilt beside itself and switched in by commit().
class ReportFolder {
 public:
  /// Refuses (CaseError) a folder that holds anything a report does not write; creates the
  /// staging folder `<out>.tmp.<pid>`.
  explicit ReportFolder(std::string out);
  ~ReportFolder();
  ReportFolder(const ReportFolder&) = delete;
  ReportFolder& operator=(const ReportFolder&) = delete;
  /// Where the new report is written.
  const std::string& staging() const { return staging_; }
  /// Exchanges the staging folder with the report folder and removes the old report.
  void commit();

 private:
  std::string out_;
  std::string staging_;
  bool committed_ = false;
};

}  // namespace bb::cli
