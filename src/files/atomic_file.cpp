#include "files/atomic_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>

#include "files/owned_temporary.hpp"

namespace bb {

namespace fs = std::filesystem;

std::string os_reason() {
  return std::strerror(errno);
}

std::string write_all(int fd, const std::string& text) {
  std::size_t at = 0;
  while (at < text.size()) {
    const ssize_t n = ::write(fd, text.data() + at, text.size() - at);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) return os_reason();
    at += static_cast<std::size_t>(n);
  }
  return "";
}

namespace {

/// Writes `text` into a file that is not replaced: a FIFO, a device, a descriptor path.
void write_in_place(const std::string& path, const std::string& text) {
  const int fd = open(path.c_str(), O_WRONLY | O_APPEND | O_CLOEXEC);
  if (fd < 0) throw WriteError(path, os_reason());
  std::string reason = write_all(fd, text);
  if (close(fd) != 0 && reason.empty()) reason = os_reason();
  if (!reason.empty()) throw WriteError(path, reason);
}

/// Paths whose files are the system's, never replaced: /dev/stdout, /proc/self/fd/3, ...
bool system_path(const std::string& path) {
  return path.rfind("/dev/", 0) == 0 || path.rfind("/proc/", 0) == 0;
}

/// Replaces the regular file `target` (or creates it) with `text` in one rename, keeping
/// the old file's permissions `mode` (0: a new file, the umask decides). The bytes go into
/// an unnamed file first, so a kill while writing leaves nothing behind.
void replace_whole(const std::string& target, mode_t mode, const std::string& text) {
  const fs::path p(target);
  const std::string dir = p.has_parent_path() ? p.parent_path().string() : ".";
  const std::string named = dir + "/." + p.filename().string() + ".beachball-" + random_token();
  const int fd = open(dir.c_str(), O_TMPFILE | O_WRONLY | O_CLOEXEC, 0644);
  if (fd < 0) {
    // A file system without unnamed files: a named temporary, removed on failure.
    write_whole_file(named, text);
    if (mode != 0) chmod(named.c_str(), mode);
  } else {
    std::string reason = write_all(fd, text);
    if (reason.empty() && mode != 0 && fchmod(fd, mode) != 0) reason = os_reason();
    if (reason.empty() && fsync(fd) != 0 && errno != EINVAL) reason = os_reason();
    const std::string self = "/proc/self/fd/" + std::to_string(fd);
    if (reason.empty() &&
        linkat(AT_FDCWD, self.c_str(), AT_FDCWD, named.c_str(), AT_SYMLINK_FOLLOW) != 0)
      reason = os_reason();
    close(fd);
    if (!reason.empty()) throw WriteError(target, reason);
  }
  if (std::rename(named.c_str(), target.c_str()) != 0) {
    const std::string reason = os_reason();
    std::remove(named.c_str());
    throw WriteError(target, reason);
  }
}

}  // namespace

void write_whole_file(const std::string& path, const std::string& text) {
  const int fd = open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) throw WriteError(path, os_reason());
  // Write everything, then fsync: a full disk may only show at the flush.
  std::string reason = write_all(fd, text);
  if (reason.empty() && fsync(fd) != 0 && errno != EINVAL) reason = os_reason();
  if (close(fd) != 0 && reason.empty()) reason = os_reason();
  if (!reason.empty()) {
    std::remove(path.c_str());
    throw WriteError(path, reason);
  }
}

void check_output_file(const std::string& path) {
  if (system_path(path)) return;
  struct stat st {};
  if (stat(path.c_str(), &st) == 0) {
    if (S_ISDIR(st.st_mode)) throw CaseError(path, 0, "is a folder, not a file to write");
    if (!S_ISREG(st.st_mode)) return;
  } else if (errno != ENOENT) {
    throw CaseError(path, 0, std::string("cannot use it: ") + std::strerror(errno));
  } else if (struct stat link{}; lstat(path.c_str(), &link) == 0) {
    throw CaseError(path, 0, "is a symbolic link to nothing; point it at a file or remove it");
  }
  // The folder the file is replaced in must take a new file.
  std::error_code ec;
  const fs::path resolved = fs::exists(path, ec) ? fs::canonical(path, ec) : fs::path(path);
  const std::string dir =
      resolved.has_parent_path() ? resolved.parent_path().string() : std::string(".");
  if (access(dir.c_str(), W_OK | X_OK) != 0)
    throw CaseError(path, 0, "cannot write into its folder " + dir + ": " + std::strerror(errno));
}

void write_output_file(const std::string& path, const std::string& text) {
  if (system_path(path)) return write_in_place(path, text);
  struct stat st {};
  if (stat(path.c_str(), &st) != 0) {
    if (errno != ENOENT) throw WriteError(path, os_reason());
    return replace_whole(path, 0, text);
  }
  if (!S_ISREG(st.st_mode)) {
    if (S_ISDIR(st.st_mode)) throw WriteError(path, "it is a folder");
    return write_in_place(path, text);
  }
  // A link is followed: the file at its end is replaced, the link stays.
  std::error_code ec;
  const fs::path target = fs::canonical(path, ec);
  if (ec) throw WriteError(path, ec.message());
  replace_whole(target.string(), st.st_mode & 07777, text);
}

}  // namespace bb
