// A digest of a file's bytes, fast enough to read every file of code a process maps (tens of
// megabytes) on each invocation: four independent lanes of 64-bit multiply-rotate rounds over
// 32-byte blocks, folded into 128 bits. Not cryptographic: it tells apart files that differ.
#pragma once

#include <string>

namespace bb {

/// 32 hexadecimal digits: a digest of the file's bytes; "" when it cannot be read. A file is
/// read once per process while its device, inode, size and modification time stay the same.
std::string file_digest(const std::string& path);

/// The same digest of `bytes` (what file_digest reads).
std::string bytes_digest(const std::string& bytes);

}  // namespace bb
