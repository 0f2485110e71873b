// A one-line progress display on a terminal: what was just done, how far along, and an
// estimate of the time left. Silent when stderr is not a terminal.
#pragma once

#include <chrono>
#include <string>

namespace bb::cli {

class Progress {
 public:
  /// `total` units of work are expected.
  explicit Progress(int total);
  ~Progress();
  Progress(const Progress&) = delete;
  Progress& operator=(const Progress&) = delete;
  /// One unit done; `what` names it.
  void advance(const std::string& what);
  /// A line to say (on stderr, "beachball: note: ..."), above the progress line.
  void note(const std::string& text);

 private:
  bool enabled_;
  int total_;
  int done_ = 0;
  std::chrono::steady_clock::time_point start_;
};

}  // namespace bb::cli
