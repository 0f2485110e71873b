// The files of one output switched into a folder together, all or nothing. They are
// written into a temporary folder of beachball's own inside the target folder (so every
// move is a rename within one file system); commit() moves each into place and keeps what
// it replaces until every move has succeeded, and a move that fails puts everything back.
// A process killed during commit() leaves a journal, and the next beachball that writes the
// folder finishes the switch (finish_interrupted_switches) before anything else.
#pragma once

#include <set>
#include <string>
#include <vector>

#include "files/atomic_file.hpp"
#include "files/owned_temporary.hpp"

namespace bb {

/// The prefix of a batch's temporary folder inside the target folder.
inline constexpr const char* kStagingPrefix = ".beachball-staging-";

class FileBatch {
 public:
  /// A batch for `folder`, which must exist; throws WriteError when its temporary folder
  /// cannot be made.
  explicit FileBatch(std::string folder);
  FileBatch(const FileBatch&) = delete;
  FileBatch& operator=(const FileBatch&) = delete;

  /// The temporary path to write `name` to now; it becomes folder/name at commit().
  std::string path_for(const std::string& name);
  /// Writes `text` as `name`.
  void write(const std::string& name, const std::string& text);
  /// The temporary path of a new, empty folder `name`, for files written into it now (by
  /// other processes too); at commit() it becomes folder/name whole, replacing an earlier
  /// one only where that holds nothing but what its own record lists, and gets a record of
  /// its own listing every file then in it.
  std::string folder_for(const std::string& name);
  /// A new, empty working folder (for a plot's script and data), gone with the batch.
  std::string work_folder(const std::string& name);
  /// At commit, `name` leaves the folder: a file of an earlier output that this one does
  /// not write again. Only names the folder's record lists are ever removed.
  void drop(const std::string& name);
  /// Files of `folder` to treat as beachball's though its record does not list them (a
  /// report written before records were kept).
  void treat_as_recorded(const std::set<std::string>& names) {
    also_recorded_.insert(names.begin(), names.end());
  }
  /// Moves every file into place and updates the folder's record of what beachball wrote.
  /// On failure everything is as it was, and WriteError says why.
  void commit();
  const std::string& folder() const { return folder_; }
  /// The names written so far.
  const std::vector<std::string>& names() const { return puts_; }

 private:
  std::string folder_;
  OwnedTemporary staging_;
  std::vector<std::string> puts_;
  std::set<std::string> folders_;  ///< the puts that are folders
  std::set<std::string> drops_;
  std::set<std::string> also_recorded_;
};

/// Finishes the switches that killed processes left half done in `folder` and removes
/// their temporary folders; call it holding the folder's lock. Returns how many it found.
int finish_interrupted_switches(const std::string& folder);

}  // namespace bb
