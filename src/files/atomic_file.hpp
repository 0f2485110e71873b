// Outputs appear whole or not at all. Every byte goes through a checked write (write,
// fsync, close, each with the OS's reason on failure) into a temporary name, and only
// complete files are renamed into place.
#pragma once

#include <string>
#include <vector>

#include "scene/case_error.hpp"

namespace bb {

/// A file that could not be written: names the path and carries the OS's reason (exit 2).
struct WriteError : CaseError {
  WriteError(const std::string& path, const std::string& reason)
      : CaseError(path, 0, "cannot write: " + reason) {}
};

/// Writes `text` to `path` (created or truncated) and makes sure every byte reached the
/// file system; throws WriteError with the OS's reason, leaving no partial file behind.
void write_whole_file(const std::string& path, const std::string& text);

/// Writes `text` to `path` through a temporary file in the same folder, then renames it.
void write_file_atomically(const std::string& path, const std::string& text);

/// The suffix of this process's temporary files, ".tmp.<pid>".
std::string temporary_suffix();

/// Files of one output written side by side under temporary names and renamed into place
/// together by commit(); destroyed uncommitted, it removes what it wrote.
class FileBatch {
 public:
  explicit FileBatch(std::string folder) : folder_(std::move(folder)) {}
  ~FileBatch();
  FileBatch(const FileBatch&) = delete;
  FileBatch& operator=(const FileBatch&) = delete;
  /// The temporary path to write `name` to now; it becomes folder/name at commit().
  std::string path_for(const std::string& name);
  /// Writes `text` as `name`.
  void write(const std::string& name, const std::string& text);
  /// Renames every file into place.
  void commit();
  const std::string& folder() const { return folder_; }

 private:
  std::string folder_;
  std::vector<std::string> names_;
  bool committed_ = false;
};

}  // namespace bb
