#include "cli/progress.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <cstdio>

namespace bb::cli {

Progress::Progress(int total)
    : enabled_(isatty(STDERR_FILENO) != 0),
      total_(std::max(total, 1)),
      start_(std::chrono::steady_clock::now()) {}

Progress::~Progress() {
  // Clear the line so that what follows starts clean.
  // fputs, not fmt::print: a destructor must not throw when the terminal went away.
  if (enabled_ && done_ > 0) std::fputs("\r\033[K", stderr);
}

void Progress::advance(const std::string& what) {
  ++done_;
  if (!enabled_) return;
  const double elapsed =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  const double left = done_ < total_ ? elapsed / done_ * (total_ - done_) : 0.0;
  fmt::print(stderr, "\r\033[K[{:>4}/{}] {:<60.60} about {:.0f} s left", std::min(done_, total_),
             total_, what, left);
  std::fflush(stderr);
}

void Progress::note(const std::string& text) {
  // The progress line is cleared first; the next advance draws it again under the note.
  fmt::print(stderr, "{}beachball: note: {}\n", enabled_ && done_ > 0 ? "\r\033[K" : "", text);
  std::fflush(stderr);
}

}  // namespace bb::cli
