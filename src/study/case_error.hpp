// The one error type for bad input: which file, which line, and what is wrong.
#pragma once

#include <stdexcept>
#include <string>

namespace bb {

class CaseError : public std::runtime_error {
 public:
  /// `line` is 1-based; 0 when the problem has no line (a missing file, say).
  CaseError(std::string file, int line, std::string problem)
      : std::runtime_error(format(file, line, problem)),
        file_(std::move(file)),
        line_(line),
        problem_(std::move(problem)) {}
  const std::string& file() const { return file_; }
  int line() const { return line_; }
  const std::string& problem() const { return problem_; }

 private:
  static std::string format(const std::string& file, int line, const std::string& problem) {
    return line > 0 ? file + ":" + std::to_string(line) + ": " + problem : file + ": " + problem;
  }
  std::string file_;
  int line_;
  std::string problem_;
};

}  // namespace bb
