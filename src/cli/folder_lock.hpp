// One writer per output folder: a second beachball writing the same folder is refused.
#pragma once

#include <string>

namespace bb::cli {

class FolderLock {
 public:
  /// Creates `folder` if needed and locks it; throws CaseError when another process holds it.
  explicit FolderLock(const std::string& folder);
  ~FolderLock();
  FolderLock(const FolderLock&) = delete;
  FolderLock& operator=(const FolderLock&) = delete;

 private:
  int fd_ = -1;
};

}  // namespace bb::cli
