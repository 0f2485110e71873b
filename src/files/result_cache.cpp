#include "files/result_cache.hpp"

#include <dirent.h>
#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <optional>
#include <vector>

#include "files/atomic_file.hpp"
#include "files/file_digest.hpp"
#include "files/owned_temporary.hpp"
#include "files/whole_file.hpp"

namespace bb {

namespace fs = std::filesystem;

namespace {

/// The first line of every entry: what wrote it and the layout's version (2: the checksum
/// covers the key).
constexpr char kMagic[] = "beachball result cache 2\n";
constexpr std::size_t kMagicSize = sizeof(kMagic) - 1;
/// The first line of the entries of the layout before, which only prune() still reads.
constexpr char kOldMagic[] = "beachball result cache 1\n";
constexpr char kSuffix[] = ".entry";
constexpr std::size_t kSuffixSize = sizeof(kSuffix) - 1;

std::uint64_t fnv1a(const std::string& bytes, std::uint64_t h) {
  for (unsigned char c : bytes) h = (h ^ c) * 0x100000001b3ULL;
  return h;
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

/// Whether `text` is lower-case hexadecimal digits only.
bool is_key_digits(const std::string& text) {
  return std::all_of(text.begin(), text.end(),
                     [](char c) { return (c >= '0' && c <= '9') || (c >= 'a' && c <= 'f'); });
}

bool is_key(const std::string& name) {
  return name.size() == 32 && is_key_digits(name);
}

/// Whether the file open as `fd` begins with this cache's first line (of this layout or the
/// one before).
bool begins_as_ours(int fd) {
  // Only the first bytes: a stream would fill a whole buffer.
  std::string head(kMagicSize, '\0');
  const ssize_t n = pread(fd, head.data(), kMagicSize, 0);
  return n == static_cast<ssize_t>(kMagicSize) && (head == kMagic || head == kOldMagic);
}

/// Whether the file at `path` begins with this cache's first line.
bool ours(const fs::path& path) {
  const int fd = open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NOFOLLOW);
  if (fd < 0) return false;
  const bool yes = begins_as_ours(fd);
  close(fd);
  return yes;
}

/// Whether `name` is an entry's name while it is being put in place: "<key>.entry.<token>".
bool entry_being_stored(const std::string& name) {
  const std::size_t at = 32 + kSuffixSize;
  return name.size() == at + 1 + 16 && is_key(name.substr(0, 32)) &&
         name.compare(32, kSuffixSize + 1, std::string(kSuffix) + ".") == 0 &&
         is_key_digits(name.substr(at + 1));
}

/// Whether the entry being stored at `path` was left by a store that is gone: it is this
/// cache's, and the lock its writer holds while it lives can be taken.
bool abandoned_store(const fs::path& path) {
  const int fd = open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NOFOLLOW);
  if (fd < 0) return false;
  struct stat st {};
  const bool free = fstat(fd, &st) == 0 && S_ISREG(st.st_mode) && begins_as_ours(fd) &&
                    flock(fd, LOCK_EX | LOCK_NB) == 0;
  close(fd);
  return free;
}

/// The checksum of an entry: its key and its payload, so that an entry read for another key
/// (its key line rewritten, say) does not pass.
std::uint64_t checksum(const std::string& key, const std::string& payload) {
  return fnv1a(payload, fnv1a(key + "\n", 0xcbf29ce484222325ULL));
}

/// The payload of `bytes`, an entry read for `key`, or nullopt when it is not whole.
std::optional<std::string> payload_of(const std::string& bytes, const std::string& key) {
  // The first line, the key, the payload's length and checksum, then the payload.
  const std::size_t header = kMagicSize + key.size() + 1 + 16;
  if (bytes.size() < header || bytes.compare(0, kMagicSize, kMagic) != 0 ||
      bytes.compare(kMagicSize, key.size() + 1, key + "\n") != 0)
    return std::nullopt;
  const std::uint64_t size = read_u64(bytes, header - 16);
  const std::uint64_t sum = read_u64(bytes, header - 8);
  if (bytes.size() - header != size) return std::nullopt;
  std::string payload = bytes.substr(header);
  if (checksum(key, payload) != sum) return std::nullopt;
  return payload;
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
  return bytes_digest(bytes);
}

ResultCache::ResultCache(std::string folder, std::uintmax_t limit_bytes)
    : folder_(std::move(folder)), limit_(limit_bytes) {}

std::string ResultCache::path_of(const std::string& key) const {
  return folder_ + "/" + key + kSuffix;
}

std::optional<std::string> ResultCache::load(const std::string& key) const {
  if (folder_.empty() || !is_key(key)) return std::nullopt;
  const std::string path = path_of(key);
  const std::optional<std::string> bytes = read_whole_file(path);
  if (!bytes) return std::nullopt;
  std::optional<std::string> payload = payload_of(*bytes, key);
  // Used now: the last to be pruned.
  if (payload) utimensat(AT_FDCWD, path.c_str(), nullptr, 0);
  return payload;
}

bool ResultCache::store(const std::string& key, const std::string& bytes) const {
  if (folder_.empty() || !is_key(key)) return false;
  try {
    std::error_code ec;
    fs::create_directories(folder_, ec);
    const std::string entry = std::string(kMagic) + key + "\n" + u64_bytes(bytes.size()) +
                              u64_bytes(checksum(key, bytes)) + bytes;
    // Written unnamed, then linked into place under a name of this invocation and renamed
    // over the entry: a reader sees the old entry or the new one. The file stays locked
    // until it is renamed, so that prune() can tell a store under way from one a kill left
    // (it removes those). Not flushed to the disk: after a power cut the checksum tells a
    // damaged entry, which is then a miss.
    const std::string named = path_of(key) + "." + random_token();
    int fd = open(folder_.c_str(), O_TMPFILE | O_WRONLY | O_CLOEXEC, 0644);
    const bool unnamed = fd >= 0;
    // A file system without unnamed files: the name first, locked before anything is in it.
    if (!unnamed) fd = open(named.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0644);
    if (fd < 0) return false;
    bool stored = flock(fd, LOCK_EX | LOCK_NB) == 0 && write_all(fd, entry).empty();
    if (stored && unnamed) {
      const std::string self = "/proc/self/fd/" + std::to_string(fd);
      stored = linkat(AT_FDCWD, self.c_str(), AT_FDCWD, named.c_str(), AT_SYMLINK_FOLLOW) == 0;
    }
    if (stored) stored = std::rename(named.c_str(), path_of(key).c_str()) == 0;
    if (!stored) std::remove(named.c_str());
    close(fd);
    return stored;
  } catch (const std::exception&) {
    return false;
  }
}

std::vector<std::string> ResultCache::damaged_entries() const {
  std::vector<std::string> damaged;
  std::error_code ec;
  for (const auto& file : fs::directory_iterator(folder_, ec)) {
    const std::string name = file.path().filename().string();
    if (!name.ends_with(kSuffix) || !is_key(name.substr(0, name.size() - kSuffixSize))) continue;
    const std::optional<std::string> bytes = read_whole_file(file.path().string());
    if (!bytes || !payload_of(*bytes, name.substr(0, 32))) damaged.push_back(name);
  }
  std::sort(damaged.begin(), damaged.end());
  return damaged;
}

std::string ResultCache::problem() const {
  struct stat st {};
  if (folder_.empty()) return "no folder is named ($HOME is not set)";
  if (stat(folder_.c_str(), &st) != 0) {
    std::error_code ec;
    fs::create_directories(folder_, ec);
    if (ec) return "it cannot be created: " + ec.message();
    if (stat(folder_.c_str(), &st) != 0)
      return std::string("it cannot be read: ") + std::strerror(errno);
  }
  if (!S_ISDIR(st.st_mode)) return "it is not a folder";
  // Another user's entries would be taken as this user's results.
  if (st.st_uid != geteuid()) return "it belongs to another user";
  if (faccessat(AT_FDCWD, folder_.c_str(), R_OK | W_OK | X_OK, AT_EACCESS) != 0)
    return std::string("it cannot be written: ") + std::strerror(errno);
  return "";
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
  std::vector<std::string> being_stored;
  std::uintmax_t total = 0;
  DIR* dir = opendir(folder_.c_str());
  if (!dir) return 0;
  while (const dirent* d = readdir(dir)) {
    const std::string name = d->d_name;
    struct stat st {};
    if (entry_being_stored(name)) being_stored.push_back(name);
    if (!name.ends_with(kSuffix) || !is_key(name.substr(0, name.size() - (sizeof(kSuffix) - 1))) ||
        fstatat(dirfd(dir), d->d_name, &st, AT_SYMLINK_NOFOLLOW) != 0 || !S_ISREG(st.st_mode))
      continue;
    entries.push_back({name, st.st_mtim, static_cast<std::uintmax_t>(st.st_size)});
    total += entries.back().size;
  }
  closedir(dir);
  // What a store killed between its link and its rename left (its writer's lock is free).
  int removed = 0;
  for (const std::string& name : being_stored)
    if (abandoned_store(fs::path(folder_) / name))
      removed += std::remove((fs::path(folder_) / name).c_str()) == 0;
  if (total <= limit_) return removed;
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
  for (const Entry& e : entries) {
    if (total <= limit_) break;
    std::error_code gone;
    if (fs::remove(fs::path(folder_) / e.name, gone)) total -= e.size, ++removed;
  }
  return removed;
}

}  // namespace bb
