#include "run/child_batch.hpp"

#include <sys/mman.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <new>

namespace bb {

namespace {

void put_u64(std::string& out, std::uint64_t v) {
  out.append(reinterpret_cast<const char*>(&v), sizeof v);
}

std::uint64_t get_u64(const std::string& bytes, std::size_t at) {
  std::uint64_t v = 0;
  std::memcpy(&v, bytes.data() + at, sizeof v);
  return v;
}

void write_or_end(int fd, const std::string& bytes) {
  std::size_t at = 0;
  while (at < bytes.size()) {
    const ssize_t n = write(fd, bytes.data() + at, bytes.size() - at);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) _exit(5);
    at += static_cast<std::size_t>(n);
  }
}

/// Everything written to `fd` (a memory file) so far.
std::string read_back(int fd) {
  std::string text;
  char buffer[65536];
  lseek(fd, 0, SEEK_SET);
  for (ssize_t n; (n = read(fd, buffer, sizeof buffer)) != 0;) {
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) break;
    text.append(buffer, static_cast<std::size_t>(n));
  }
  return text;
}

}  // namespace

std::string encode_frame(const ChildFrame& frame) {
  std::string out;
  put_u64(out, frame.payload.size());
  out += frame.payload;
  put_u64(out, frame.console.size());
  out += frame.console;
  std::uint64_t bits = 0;
  std::memcpy(&bits, &frame.seconds, sizeof bits);
  put_u64(out, bits);
  return out;
}

std::optional<ChildFrame> take_frame(std::string& bytes) {
  constexpr std::size_t word = sizeof(std::uint64_t);
  if (bytes.size() < word) return std::nullopt;
  const std::uint64_t payload = get_u64(bytes, 0);
  if (bytes.size() < word + payload + word) return std::nullopt;
  const std::uint64_t console = get_u64(bytes, word + payload);
  const std::size_t size = word + payload + word + console + word;
  if (bytes.size() < size) return std::nullopt;
  ChildFrame frame{bytes.substr(word, payload), bytes.substr(2 * word + payload, console), 0.0};
  const std::uint64_t bits = get_u64(bytes, size - word);
  std::memcpy(&frame.seconds, &bits, sizeof bits);
  bytes.erase(0, size);
  return frame;
}

void run_batch_child(const std::vector<std::function<std::string()>>& works, int result_fd) {
  const int shared_out = dup(STDOUT_FILENO), shared_err = dup(STDERR_FILENO);
  for (const auto& work : works) {
    // The piece prints into a memory file of its own, read back once it is done.
    const int caught = memfd_create("beachball-console", MFD_CLOEXEC);
    if (caught < 0) _exit(6);
    std::fflush(nullptr);
    dup2(caught, STDOUT_FILENO);
    dup2(caught, STDERR_FILENO);
    const auto start = std::chrono::steady_clock::now();
    ChildFrame frame;
    try {
      frame.payload = work();
    } catch (const std::bad_alloc&) {
      _exit(3);
    } catch (const std::exception&) {
      _exit(4);
    }
    std::fflush(nullptr);
    frame.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    dup2(shared_out, STDOUT_FILENO);
    dup2(shared_err, STDERR_FILENO);
    frame.console = read_back(caught);
    close(caught);
    write_or_end(result_fd, encode_frame(frame));
  }
  std::fflush(nullptr);
  _exit(0);
}

}  // namespace bb
