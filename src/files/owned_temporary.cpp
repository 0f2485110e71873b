#include "files/owned_temporary.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/random.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>

#include "files/atomic_file.hpp"

namespace bb {

namespace fs = std::filesystem;

namespace {

constexpr const char* kMarkerText =
    "beachball made this folder for its own temporary files and removes it when done\n";

/// Reads at most `limit` bytes of the file open as `fd`.
std::string read_some(int fd, std::size_t limit) {
  std::string text(limit, '\0');
  std::size_t at = 0;
  while (at < limit) {
    const ssize_t n = ::read(fd, text.data() + at, limit - at);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;
    at += static_cast<std::size_t>(n);
  }
  text.resize(at);
  return text;
}

}  // namespace

std::string random_token() {
  unsigned char bytes[8];
  std::size_t got = 0;
  while (got < sizeof bytes) {
    const ssize_t n = getrandom(bytes + got, sizeof bytes - got, 0);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) throw WriteError("getrandom", os_reason());
    got += static_cast<std::size_t>(n);
  }
  static const char* digits = "0123456789abcdef";
  std::string token;
  for (unsigned char b : bytes) {
    token += digits[b >> 4];
    token += digits[b & 15];
  }
  return token;
}

int mark_as_owned(const std::string& folder) {
  const std::string marker = folder + "/" + kOwnerMarker;
  const int fd = open(marker.c_str(), O_RDWR | O_CREAT | O_EXCL | O_CLOEXEC | O_NOFOLLOW, 0600);
  if (fd < 0) throw WriteError(marker, os_reason());
  // The lock first: from here on nobody judges the folder abandoned.
  if (flock(fd, LOCK_EX | LOCK_NB) != 0) {
    const std::string reason = os_reason();
    close(fd);
    throw WriteError(marker, "cannot lock: " + reason);
  }
  const std::string text = kMarkerText;
  if (::write(fd, text.data(), text.size()) != static_cast<ssize_t>(text.size())) {
    const std::string reason = os_reason();
    close(fd);
    std::remove(marker.c_str());
    throw WriteError(marker, reason);
  }
  return fd;
}

bool abandoned_marker(const std::string& marker) {
  const int fd = open(marker.c_str(), O_RDONLY | O_CLOEXEC | O_NOFOLLOW);
  if (fd < 0) return false;
  struct stat st {};
  const bool ours = fstat(fd, &st) == 0 && S_ISREG(st.st_mode) &&
                    read_some(fd, std::strlen(kMarkerText) + 1) == kMarkerText;
  // A lock we can take means the process that made the marker is gone.
  const bool free = ours && flock(fd, LOCK_EX | LOCK_NB) == 0;
  close(fd);
  return free;
}

bool remove_owned_folder(const std::string& folder) {
  std::error_code ec;
  bool only_marker_left = true;
  for (const auto& entry : fs::directory_iterator(folder, ec)) {
    if (entry.path().filename() == kOwnerMarker) continue;
    std::error_code remove_error;
    fs::remove_all(entry.path(), remove_error);
    only_marker_left = only_marker_left && !remove_error;
  }
  // The marker goes only once nothing else is left, then the empty folder.
  if (ec || !only_marker_left) return false;
  std::remove((folder + "/" + kOwnerMarker).c_str());
  return rmdir(folder.c_str()) == 0;
}

int remove_abandoned_temporaries(const std::string& parent, const std::string& prefix) {
  int removed = 0;
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(parent, ec)) {
    const std::string name = entry.path().filename().string();
    if (name.rfind(prefix, 0) != 0) continue;
    // A symbolic link is never followed: only a real folder holding our marker goes.
    std::error_code kind_error;
    if (!entry.is_directory(kind_error) || entry.is_symlink(kind_error)) continue;
    if (!abandoned_marker((entry.path() / kOwnerMarker).string())) continue;
    removed += remove_owned_folder(entry.path().string());
  }
  return removed;
}

OwnedTemporary::OwnedTemporary(const std::string& parent, const std::string& prefix) {
  path_ = parent + "/" + prefix + random_token();
  if (mkdir(path_.c_str(), 0700) != 0) {
    const std::string reason = os_reason();
    path_.clear();
    throw WriteError(parent + "/" + prefix + "...", "cannot create a temporary folder: " + reason);
  }
  try {
    marker_fd_ = mark_as_owned(path_);
  } catch (...) {
    rmdir(path_.c_str());
    throw;
  }
}

void OwnedTemporary::remove() {
  if (!released_ && !path_.empty()) remove_owned_folder(path_);
  path_.clear();
  if (marker_fd_ >= 0) close(marker_fd_);
  marker_fd_ = -1;
}

OwnedTemporary::~OwnedTemporary() {
  remove();
}

}  // namespace bb
