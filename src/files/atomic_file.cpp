#include "report/atomic_file.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>

namespace bb {

namespace {

std::string os_reason() {
  return std::strerror(errno);
}

}  // namespace

std::string temporary_suffix() {
  return ".tmp." + std::to_string(getpid());
}

void write_whole_file(const std::string& path, const std::string& text) {
  const int fd = open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) throw WriteError(path, os_reason());
  std::size_t at = 0;
  // Write everything, then fsync: a full disk may only show at the flush.
  while (at < text.size()) {
    const ssize_t n = ::write(fd, text.data() + at, text.size() - at);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) {
      const std::string reason = os_reason();
      close(fd);
      std::remove(path.c_str());
      throw WriteError(path, reason);
    }
    at += static_cast<std::size_t>(n);
  }
  if (fsync(fd) != 0 && errno != EINVAL) {
    const std::string reason = os_reason();
    close(fd);
    std::remove(path.c_str());
    throw WriteError(path, reason);
  }
  if (close(fd) != 0) {
    const std::string reason = os_reason();
    std::remove(path.c_str());
    throw WriteError(path, reason);
  }
}

void write_file_atomically(const std::string& path, const std::string& text) {
  const std::string temporary = path + temporary_suffix();
  write_whole_file(temporary, text);
  if (std::rename(temporary.c_str(), path.c_str()) != 0) {
    const std::string reason = os_reason();
    std::remove(temporary.c_str());
    throw WriteError(path, reason);
  }
}

FileBatch::~FileBatch() {
  if (committed_) return;
  for (const std::string& name : names_)
    std::remove((folder_ + "/" + name + temporary_suffix()).c_str());
}

std::string FileBatch::path_for(const std::string& name) {
  names_.push_back(name);
  return folder_ + "/" + name + temporary_suffix();
}

void FileBatch::write(const std::string& name, const std::string& text) {
  write_whole_file(path_for(name), text);
}

void FileBatch::commit() {
  for (const std::string& name : names_) {
    const std::string target = folder_ + "/" + name;
    if (std::rename((target + temporary_suffix()).c_str(), target.c_str()) != 0)
      throw WriteError(target, os_reason());
  }
  committed_ = true;
}

}  // namespace bb
