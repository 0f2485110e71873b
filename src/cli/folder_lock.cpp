#include "cli/folder_lock.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <filesystem>

#include "study/case_error.hpp"

namespace bb::cli {

FolderLock::FolderLock(const std::string& folder) {
  std::error_code ec;
  std::filesystem::create_directories(folder, ec);
  if (ec) throw CaseError(folder, 0, "cannot create the output folder: " + ec.message());
  // The lock is on the folder itself, so no lock file is left behind.
  fd_ = open(folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd_ < 0) throw CaseError(folder, 0, "cannot open the output folder");
  if (flock(fd_, LOCK_EX | LOCK_NB) != 0) {
    close(fd_);
    fd_ = -1;
    throw CaseError(folder, 0,
                    "another beachball is writing this folder right now; wait for it to finish or "
                    "choose another --out");
  }
}

FolderLock::~FolderLock() {
  if (fd_ >= 0) close(fd_);
}

}  // namespace bb::cli
