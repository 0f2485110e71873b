// Temporary folders beachball can prove are its own. Each holds a marker file whose text
// says beachball made it, and the process that made it keeps an exclusive flock on that
// marker for as long as it lives (forked children share it). A later run removes such a
// folder only when the marker is there and nobody holds its lock: never by the shape of a
// name, and never by a process id (which may belong to another PID namespace).
#pragma once

#include <string>

namespace bb {

/// The marker's file name inside an owned temporary folder.
inline constexpr const char* kOwnerMarker = ".beachball-owner";

/// A random token of 16 hexadecimal digits, different for every call.
std::string random_token();

class OwnedTemporary {
 public:
  /// Creates the folder `parent/<prefix><token>` with its marker, and locks the marker.
  /// Throws WriteError with the OS's reason.
  OwnedTemporary(const std::string& parent, const std::string& prefix);
  /// Removes the folder and everything in it, unless released.
  ~OwnedTemporary();
  OwnedTemporary(const OwnedTemporary&) = delete;
  OwnedTemporary& operator=(const OwnedTemporary&) = delete;

  const std::string& path() const { return path_; }
  /// Removes the folder now, and everything in it.
  void remove();
  /// From now on the folder is not removed by this object (its marker stays locked until
  /// the object goes).
  void release() { released_ = true; }

 private:
  std::string path_;
  int marker_fd_ = -1;
  bool released_ = false;
};

/// Writes a marker into `folder` and locks it; returns the locked descriptor (close it to
/// unlock). Throws WriteError.
int mark_as_owned(const std::string& folder);

/// Whether `marker` (a path) is a beachball marker nobody holds: its text is beachball's
/// and its lock can be taken now.
bool abandoned_marker(const std::string& marker);

/// Removes `folder`, which holds beachball's marker, with the marker last: a kill part-way
/// leaves the folder still marked, for the next run to finish, never an unmarked folder
/// nobody can prove is beachball's. Returns whether it is gone.
bool remove_owned_folder(const std::string& folder);

/// Removes every folder `parent/<prefix>*` that holds an abandoned marker; returns how many.
/// Anything else (a user's folder of the same shape of name) is left alone.
int remove_abandoned_temporaries(const std::string& parent, const std::string& prefix);

}  // namespace bb
