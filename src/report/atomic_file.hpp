// Outputs appear whole or not at all: written to a temporary file, then renamed.
#pragma once

#include <string>

namespace bb {

/// Writes `text` to `path` through a temporary file in the same folder; throws
/// std::runtime_error naming the path on failure.
void write_file_atomically(const std::string& path, const std::string& text);

}  // namespace bb
