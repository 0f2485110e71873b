// Temporaries as a killed beachball leaves them: made by a process that is gone, so their
// marker's lock is free.
#pragma once

#include <sys/wait.h>
#include <unistd.h>

#include <string>

#include "files/owned_temporary.hpp"

namespace bb::test {

/// An owned temporary folder `parent/<prefix>...` whose maker has died; returns its path.
inline std::string abandoned_temporary(const std::string& parent, const std::string& prefix) {
  int fds[2];
  if (pipe(fds) != 0) return "";
  const pid_t pid = fork();
  if (pid == 0) {
    close(fds[0]);
    OwnedTemporary folder(parent, prefix);
    folder.release();
    const std::string& path = folder.path();
    if (write(fds[1], path.data(), path.size()) < 0) _exit(1);
    _exit(0);
  }
  close(fds[1]);
  std::string path;
  char buffer[512];
  for (ssize_t n; (n = read(fds[0], buffer, sizeof buffer)) > 0;) path.append(buffer, n);
  close(fds[0]);
  waitpid(pid, nullptr, 0);
  return path;
}

}  // namespace bb::test
