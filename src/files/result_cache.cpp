#include "files/result_cache.hpp"

#include <dirent.h>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <vector>

#include "files/atomic_file.hpp"
#include "files/owned_temporary.hpp"

namespace bb {

namespace fs = std::filesystem;

namespace {

/// The first line of every entry: what wrote it and the layout's version.
constexpr char kMagic[] = "beachball result cache 1\n";
constexpr std::size_t kMagicSize = sizeof(kMagic) - 1;
constexpr char kSuffix[] = ".entry";

std::uint64_t fnv1a(const std::string& bytes, std::uint64_t h) {
  for (unsigned char c : bytes) h = (h ^ c) * 0x100000001b3ULL;
  return h;
}

/// A second hash of another structure (multiply-rotate), so that the two halves of a digest
/// do not fail together.
std::uint64_t mix(const std::string& bytes) {
  std::uint64_t h = 0x9e3779b97f4a7c15ULL ^ bytes.size();
  for (unsigned char c : bytes) {
    h += c;
    h *= 0xbf58476d1ce4e5b9ULL;
    h ^= h >> 29;
  }
  return h;
}

std::string hex(std::uint64_t v) {
  static const char* digits = "0123456789abcdef";
  std::string out(16, '0');
  for (int i = 15; i >= 0; --i, v >>= 4) out[i] = digits[v & 15];
  return out;
}

std::string u64_bytes(std::uint64_t v) {
  std::string out(8, '\0');
  std::memcpy(out.data(), &v, 8);
  return out;
}

std::uint64_t read_u64(const std::string& bytes, std::size_t at) {
  std::uint64_t v = 0;
  std::memcpy(&v, bytes.data() + at, 8);
  return v;
}

bool is_key(const std::string& name) {
  return name.size() == 32 && std::all_of(name.begin(), name.end(), [](char c) {
           return (c >= '0' && c <= '9') || (c >= 'a' && c <= 'f');
         });
}

/// Whether the file at `path` begins with this cache's first line.
bool ours(const fs::path& path) {
  // Only the first bytes: a stream would fill a whole buffer.
  const int fd = open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) return false;
  std::string head(kMagicSize, '\0');
  const ssize_t n = pread(fd, head.data(), kMagicSize, 0);
  close(fd);
  return n == static_cast<ssize_t>(kMagicSize) && head == kMagic;
}

}  // namespace

std::string default_cache_folder() {
  if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && *xdg == '/')
    return std::string(xdg) + "/beachball";
  if (const char* home = std::getenv("HOME"); home && *home == '/')
    return std::string(home) + "/.cache/beachball";
  return "";
}

std::string digest(const std::string& bytes) {
  return hex(fnv1a(bytes, 0xcbf29ce484222325ULL)) + hex(mix(bytes));
}

ResultCache::ResultCache(std::string folder, std::uintmax_t limit_bytes)
    : folder_(std::move(folder)), limit_(limit_bytes) {}

std::string ResultCache::path_of(const std::string& key) const {
  return folder_ + "/" + key + kSuffix;
}

std::optional<std::string> ResultCache::load(const std::string& key) const {
  const std::string path = path_of(key);
  std::ifstream in(path, std::ios::binary);
  if (!in) return std::nullopt;
  const std::string bytes((std::istreambuf_iterator<char>(in)), {});
  // The first line, the key, the payload's length and checksum, then the payload.
  const std::size_t header = kMagicSize + key.size() + 1 + 16;
  if (bytes.size() < header || bytes.compare(0, kMagicSize, kMagic) != 0 ||
      bytes.compare(kMagicSize, key.size() + 1, key + "\n") != 0)
    return std::nullopt;
  const std::uint64_t size = read_u64(bytes, header - 16);
  const std::uint64_t sum = read_u64(bytes, header - 8);
  if (bytes.size() - header != size) return std::nullopt;
  std::string payload = bytes.substr(header);
  if (fnv1a(payload, 0xcbf29ce484222325ULL) != sum) return std::nullopt;
  // Used now: the last to be pruned.
  utimensat(AT_FDCWD, path.c_str(), nullptr, 0);
  return payload;
}

bool ResultCache::store(const std::string& key, const std::string& bytes) const {
  if (folder_.empty() || !is_key(key)) return false;
  try {
    std::error_code ec;
    fs::create_directories(folder_, ec);
    const std::string entry = std::string(kMagic) + key + "\n" + u64_bytes(bytes.size()) +
                              u64_bytes(fnv1a(bytes, 0xcbf29ce484222325ULL)) + bytes;
    // Unnamed, then linked into place under a name of this invocation and renamed over the
    // entry: a reader sees the old entry or the new one. Not flushed to the disk: after a
    // power cut the checksum tells a damaged entry, which is then a miss.
    const int fd = open(folder_.c_str(), O_TMPFILE | O_WRONLY | O_CLOEXEC, 0644);
    if (fd < 0) {
      write_output_file(path_of(key), entry);
      return true;
    }
    std::size_t at = 0;
    while (at < entry.size()) {
      const ssize_t n = ::write(fd, entry.data() + at, entry.size() - at);
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0) break;
      at += static_cast<std::size_t>(n);
    }
    const std::string self = "/proc/self/fd/" + std::to_string(fd);
    const std::string named = path_of(key) + "." + random_token();
    const bool linked = at == entry.size() && linkat(AT_FDCWD, self.c_str(), AT_FDCWD,
                                                     named.c_str(), AT_SYMLINK_FOLLOW) == 0;
    close(fd);
    if (!linked) return false;
    if (std::rename(named.c_str(), path_of(key).c_str()) != 0) {
      std::remove(named.c_str());
      return false;
    }
    return true;
  } catch (const std::exception&) {
    return false;
  }
}

int ResultCache::prune() const {
  struct Entry {
    std::string name;
    struct timespec used;
    std::uintmax_t size;
  };
  // Names and one stat each (a folder of tens of thousands of entries); the entries' first
  // bytes are read only when the folder is over its limit.
  std::vector<Entry> entries;
  std::uintmax_t total = 0;
  DIR* dir = opendir(folder_.c_str());
  if (!dir) return 0;
  while (const dirent* d = readdir(dir)) {
    const std::string name = d->d_name;
    struct stat st {};
    if (!name.ends_with(kSuffix) || !is_key(name.substr(0, name.size() - (sizeof(kSuffix) - 1))) ||
        fstatat(dirfd(dir), d->d_name, &st, AT_SYMLINK_NOFOLLOW) != 0 || !S_ISREG(st.st_mode))
      continue;
    entries.push_back({name, st.st_mtim, static_cast<std::uintmax_t>(st.st_size)});
    total += entries.back().size;
  }
  closedir(dir);
  if (total <= limit_) return 0;
  // Over the limit: only beachball's entries count, and only they may go.
  std::erase_if(entries, [&](const Entry& e) {
    if (ours(fs::path(folder_) / e.name)) return false;
    total -= e.size;
    return true;
  });
  std::sort(entries.begin(), entries.end(), [](const Entry& a, const Entry& b) {
    return a.used.tv_sec != b.used.tv_sec ? a.used.tv_sec < b.used.tv_sec
                                          : a.used.tv_nsec < b.used.tv_nsec;
  });
  int removed = 0;
  for (const Entry& e : entries) {
    if (total <= limit_) break;
    std::error_code gone;
    if (fs::remove(fs::path(folder_) / e.name, gone)) total -= e.size, ++removed;
  }
  return removed;
}

}  // namespace bb
