// Outputs appear whole or not at all. Every byte goes through a checked write (write,
// fsync, close, each with the OS's reason on failure); a file that replaces another is
// written unnamed (O_TMPFILE) and only linked into place when complete.
#pragma once

#include <string>

#include "study/case_error.hpp"

namespace bb {

/// Why the last system call failed, in the OS's words (strerror of errno).
std::string os_reason();

/// Writes all of `text` to the open file `fd`, again after an interrupted call; on failure
/// the OS's reason, else "".
std::string write_all(int fd, const std::string& text);

/// A file that could not be written: names the path and carries the OS's reason (exit 2).
struct WriteError : CaseError {
  WriteError(const std::string& path, const std::string& reason)
      : CaseError(path, 0, "cannot write: " + reason) {}
};

/// Writes `text` to `path` (created or truncated) and makes sure every byte reached the
/// file system; throws WriteError with the OS's reason, leaving no partial file behind.
void write_whole_file(const std::string& path, const std::string& text);

/// Writes `text` to the output file `path` the user named. A regular file (or a path that
/// does not exist yet) is replaced whole, at the end of any symbolic links, in one rename:
/// readers see the old file or the new one. Anything else (a FIFO, a character device such
/// as /dev/stdout or /dev/null, a path under /dev or /proc) is written directly and stays
/// what it is.
void write_output_file(const std::string& path, const std::string& text);

/// Throws CaseError, before any work, when `path` cannot take an output file: it is a
/// folder, a dangling link, or its folder cannot be written.
void check_output_file(const std::string& path);

}  // namespace bb
