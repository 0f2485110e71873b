// A folder of kept results, each under a key made of everything that decides it (the
// caller makes the key). An entry is written unnamed and linked into place whole, and
// carries its length and a checksum: a reader never takes a half-written or damaged entry
// (it is a miss, and the next store replaces it), and its checksum covers its key, so an
// entry is never read for another key. Two processes may share the folder: the
// same key always holds the same bytes, and the last link wins. The folder is bounded:
// prune() removes the entries used longest ago until it is under its limit.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace bb {

/// $XDG_CACHE_HOME/beachball, or $HOME/.cache/beachball; "" when neither is set.
std::string default_cache_folder();

/// 32 hexadecimal digits: a 128-bit digest of `bytes` (not cryptographic: it tells apart
/// inputs that differ, it does not stand up to an adversary).
std::string digest(const std::string& bytes);

class ResultCache {
 public:
  /// Kept results under `folder` (created when first stored to), at most `limit_bytes`.
  ResultCache(std::string folder, std::uintmax_t limit_bytes);
  const std::string& folder() const { return folder_; }
  /// The bytes kept under `key`, or nullopt: none, or an entry that is damaged, not
  /// beachball's, or kept under another key. A hit marks the entry as used now.
  std::optional<std::string> load(const std::string& key) const;
  /// Keeps `bytes` under `key`. A cache that cannot be written is no error: false.
  bool store(const std::string& key, const std::string& bytes) const;
  /// Removes what stores killed part-way left, then the entries used longest ago until the
  /// kept bytes are within the limit; only files that are this cache's entries (their name a
  /// key, their first line this cache's). Returns how many it removed.
  int prune() const;
  /// The names of the entries in the folder that are not whole (cut short, damaged, or with
  /// a key line that is not their own), in name order.
  std::vector<std::string> damaged_entries() const;
  /// Why results cannot be kept in the folder (it is not a folder, belongs to another user,
  /// cannot be created or written), or "" when they can. Creates a missing folder.
  std::string problem() const;

 private:
  std::string path_of(const std::string& key) const;
  std::string folder_;
  std::uintmax_t limit_;
};

}  // namespace bb
