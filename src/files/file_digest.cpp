#include "files/file_digest.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdint>
#include <cstring>
#include <map>
#include <mutex>
#include <tuple>

namespace bb {

namespace {

constexpr std::uint64_t kPrime1 = 0x9E3779B185EBCA87ULL;
constexpr std::uint64_t kPrime2 = 0xC2B2AE3D27D4EB4FULL;
constexpr std::uint64_t kPrime3 = 0x165667B19E3779F9ULL;

std::uint64_t rotl(std::uint64_t v, int r) {
  return (v << r) | (v >> (64 - r));
}

std::uint64_t lane_round(std::uint64_t lane, std::uint64_t word) {
  return rotl(lane + word * kPrime2, 31) * kPrime1;
}

std::uint64_t avalanche(std::uint64_t h) {
  h ^= h >> 33;
  h *= kPrime2;
  h ^= h >> 29;
  h *= kPrime3;
  return h ^ (h >> 32);
}

std::string hex(std::uint64_t v) {
  static const char* digits = "0123456789abcdef";
  std::string out(16, '0');
  for (int i = 15; i >= 0; --i, v >>= 4) out[i] = digits[v & 15];
  return out;
}

/// The running state: four lanes, the bytes taken so far, and a partial block.
class LaneHash {
 public:
  void add(const unsigned char* bytes, std::size_t n) {
    length_ += n;
    // Top up a partial block first.
    while (n > 0 && filled_ > 0) {
      block_[filled_++] = *bytes++, --n;
      if (filled_ == 32) take(block_), filled_ = 0;
    }
    for (; n >= 32; bytes += 32, n -= 32) take(bytes);
    std::memcpy(block_, bytes, n);
    filled_ = n;
  }
  std::string finish() {
    // The tail bytes, one at a time, into lanes by their place; then the length.
    for (std::size_t i = 0; i < filled_; ++i)
      lanes_[i % 4] = lane_round(lanes_[i % 4], block_[i] + 1);
    const std::uint64_t a = rotl(lanes_[0], 1) + rotl(lanes_[1], 7) + rotl(lanes_[2], 12) +
                            rotl(lanes_[3], 18) + length_;
    const std::uint64_t b =
        (lanes_[0] * kPrime3) ^ rotl(lanes_[1], 29) ^ (lanes_[2] * kPrime1) ^ rotl(lanes_[3], 41);
    return hex(avalanche(a)) + hex(avalanche(b ^ (length_ * kPrime2)));
  }

 private:
  void take(const unsigned char* block) {
    for (int lane = 0; lane < 4; ++lane) {
      std::uint64_t word = 0;
      std::memcpy(&word, block + 8 * lane, 8);
      lanes_[lane] = lane_round(lanes_[lane], word);
    }
  }
  std::uint64_t lanes_[4] = {kPrime1 + kPrime2, kPrime2, 0, 0 - kPrime1};
  std::uint64_t length_ = 0;
  unsigned char block_[32] = {};
  std::size_t filled_ = 0;
};

/// What tells one version of a file from another without reading it.
using FileVersion = std::tuple<std::string, dev_t, ino_t, off_t, time_t, long>;

}  // namespace

std::string bytes_digest(const std::string& bytes) {
  LaneHash h;
  h.add(reinterpret_cast<const unsigned char*>(bytes.data()), bytes.size());
  return h.finish();
}

std::string file_digest(const std::string& path) {
  static std::mutex mutex;
  static std::map<FileVersion, std::string> read;
  const int fd = open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) return "";
  struct stat st {};
  if (fstat(fd, &st) != 0) {
    close(fd);
    return "";
  }
  const FileVersion version{path,       st.st_dev,   st.st_ino,
                            st.st_size, st.st_mtime, st.st_mtim.tv_nsec};
  {
    const std::lock_guard lock(mutex);
    if (const auto found = read.find(version); found != read.end()) {
      close(fd);
      return found->second;
    }
  }
  LaneHash h;
  // A block on the stack, left uncleared: a megabyte zeroed on the heap at each call cost
  // more than hashing the program itself (a fresh mapping, its pages faulted in and cleared).
  unsigned char buffer[1 << 16];
  for (;;) {
    const ssize_t n = ::read(fd, buffer, sizeof buffer);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) {
      close(fd);
      return "";
    }
    if (n == 0) break;
    h.add(buffer, static_cast<std::size_t>(n));
  }
  close(fd);
  const std::string digest = h.finish();
  const std::lock_guard lock(mutex);
  read.emplace(version, digest);
  return digest;
}

}  // namespace bb
