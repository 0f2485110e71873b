// A file's bytes read whole, in blocks: a character at a time through a stream iterator
// costs tens of nanoseconds a byte, and results, cached runs and trajectories run to megabytes.
#pragma once

#include <optional>
#include <string>

namespace bb {

/// Every byte of the file at `path`; nullopt when it cannot be opened or a read fails.
std::optional<std::string> read_whole_file(const std::string& path);

}  // namespace bb
