// Where a command's outputs go. Everything that can refuse a folder is checked before any
// run starts; the folder is locked before anything in it is touched; and beachball only
// ever replaces or removes what it can prove it wrote (the folder's record, or a temporary
// folder holding its marker), never a file because of the shape of its name.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "cli/folder_lock.hpp"
#include "files/file_batch.hpp"
#include "files/owned_temporary.hpp"
#include "study/scene.hpp"

namespace bb::cli {

/// Throws CaseError (exit 2) naming the case file and its `name` line when an output file
/// of `scene` would have a name longer than the file system allows.
void check_output_names(const Scene& scene);

/// Throws CaseError with the OS's reason when `folder` cannot be created or written.
void check_writable(const std::string& folder);

/// The output folder of `run`, `report` or `stability`: `--out` with its symbolic links
/// followed (the folder a link points to is written, and the link stays), created when
/// missing, locked against a second beachball, and then cleared of what killed runs left
/// in it (their half-done switches finished, their temporary folders removed).
class OutputFolder {
 public:
  explicit OutputFolder(const std::string& given);
  /// Removes the folder again when this made it and nothing was written into it (a command
  /// that stopped before its outputs leaves no empty folder).
  ~OutputFolder();
  OutputFolder(const OutputFolder&) = delete;
  OutputFolder& operator=(const OutputFolder&) = delete;
  /// The folder as the user named it, for messages.
  const std::string& given() const { return given_; }
  /// The real folder written.
  const std::string& path() const { return path_; }

 private:
  std::string given_;
  std::string path_;
  bool made_ = false;  ///< this created the folder
  std::unique_ptr<FolderLock> lock_;
};

/// Throws CaseError before any work when one of `names` exists in `folder` and is not a
/// plain file beachball wrote there (its record lists it).
void check_outputs_are_ours(const std::string& folder, const std::vector<std::string>& names);

/// Throws CaseError before any work when the trajectories folder of case `name`
/// (trajectory_names.hpp) exists in `folder` and `run` would replace or remove it without
/// having written all of it: when `writing` (--trajectories) or when the record lists it (a
/// run drops its case's earlier set), it must be a folder the record lists, holding only the
/// files its own record lists. A folder of that name the record does not list is left alone
/// by a run that does not write one.
void check_trajectories_are_ours(const std::string& folder, const std::string& name, bool writing);

/// The files of `folder` that an earlier output of case `name` wrote and its record lists:
/// <name>.json, .csv, .md, its plots <name>-*.svg and its trajectories folder (for `run`,
/// which replaces a case's set).
std::vector<std::string> recorded_case_files(const std::string& folder, const std::string& name);

/// A report replaces its whole folder. When the folder can be renamed, the new report is
/// built in a temporary folder beside it and the two are exchanged in one rename, so a
/// reader sees the old report or the new one. When it cannot (a mount point, the current
/// folder or one above it, a parent that cannot be written), the new report is built inside
/// it and switched in file by file, all or nothing (FileBatch).
class ReportFolder {
 public:
  /// Refuses (CaseError) a folder that holds anything beachball did not write there.
  explicit ReportFolder(const OutputFolder& out);
  ~ReportFolder();
  ReportFolder(const ReportFolder&) = delete;
  ReportFolder& operator=(const ReportFolder&) = delete;
  /// The folder a FileBatch for the new report writes into.
  const std::string& target() const;
  /// Adds to `batch` the removal of the old report's files (switched file by file only).
  void drop_old_report(FileBatch& batch) const;
  /// Once the batch is committed: puts the new report in place of the old one.
  void commit();
  /// Whether the report is switched in file by file, and why (empty when exchanged whole).
  const std::string& by_files_because() const { return by_files_because_; }

 private:
  std::string out_;
  std::string by_files_because_;
  std::unique_ptr<OwnedTemporary> beside_;
};

}  // namespace bb::cli
