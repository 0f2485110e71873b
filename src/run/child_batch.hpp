// Several pieces of a ChildPool run one after another in one child (child_pool.hpp's groups):
// each piece's result goes back as a frame (its bytes, what it printed, its seconds), so each
// piece keeps the outcome and the console its own child would have given it.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace bb {

/// One piece's result from a shared child.
struct ChildFrame {
  std::string payload;   ///< what the work returned
  std::string console;   ///< what it printed, to stdout and stderr
  double seconds = 0.0;  ///< its wall time in the child
};

/// The frame's bytes on the pipe.
std::string encode_frame(const ChildFrame& frame);
/// Takes the first whole frame off the front of `bytes`; nullopt while it is incomplete.
std::optional<ChildFrame> take_frame(std::string& bytes);

/// Runs in a shared child: each of `works` in turn, its stdout and stderr caught apart from
/// the others', its frame written to `result_fd` when it is done. A piece that throws ends
/// the child at once (exit code 4, or 3 out of memory): the pieces not framed then run again,
/// each in a child of its own.
[[noreturn]] void run_batch_child(const std::vector<std::function<std::string()>>& works,
                                  int result_fd);

}  // namespace bb
