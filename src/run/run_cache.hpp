// Results kept between invocations (files/result_cache.hpp), so that only what changed runs
// again. A run's key is made of everything that decides it: the case's text as loaded and
// what was changed in it (a sweep's point), what is kept (an accuracy run, the reference,
// its self-check, a stability trial, a sweep's point), the backend and its step, and the
// build: this program's bytes, the engine plugin's bytes and its library's version. Any
// edit of a case file reruns that case's runs; a rebuild reruns everything. Only results
// that another run would repeat are kept: a crash or a timeout is run again.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "files/result_cache.hpp"
#include "run/registry.hpp"
#include "run/results.hpp"

namespace bb {

/// The most bytes a cache folder keeps before the entries used longest ago go.
inline constexpr std::uintmax_t kCacheLimitBytes = 1ULL << 30;

/// A digest of this program's bytes: which build made a result.
std::string program_digest();

class RunCache {
 public:
  /// Kept results in `folder`; with `fresh`, none is reused (new ones are still kept).
  RunCache(const std::string& folder, bool fresh);
  const std::string& folder() const { return store_.folder(); }
  /// The folder's entries themselves (other kept things share it: a report's drawings).
  const ResultCache& store() const { return store_; }
  /// Whether nothing kept is reused (--fresh).
  bool fresh() const { return fresh_; }

  /// The key of what `role` keeps of `backend` (a name; the reference's is its own) on
  /// `scene` at `dt` (nullopt for the reference's own steps); "" when the scene has no text
  /// (made in code): such a run is never kept.
  std::string key(const Scene& scene, const std::string& role, const Backend& backend,
                  std::optional<double> dt) const;
  /// The same for what does not belong to one backend (a sweep's point: `what` names it).
  std::string key(const Scene& scene, const std::string& role, const std::string& what) const;

  /// The bytes kept under `key` (counted as reused), or nullopt (counted as run; an empty
  /// key, for a run that is never kept, too).
  std::optional<std::string> find(const std::string& key);
  /// The bytes of every key, counted as reused, when every one is kept; else nullopt, each
  /// counted as run (runs that belong together: one is reused only with the others).
  std::optional<std::vector<std::string>> find_all(const std::vector<std::string>& keys);
  void keep(const std::string& key, const std::string& bytes) const;

  /// Whether a run with this outcome is the same every time it runs (and so may be kept).
  static bool repeatable(const RunRecord& run);

  /// From now on a key that is not kept stops the work: find() throws CaseError naming
  /// `where` and `why` (a merge of shards, which must hold every keepable result).
  void require_kept(std::string where, std::string why) {
    require_where_ = std::move(where), require_why_ = std::move(why);
  }
  /// A digest of this program's bytes: which build made the kept results.
  const std::string& program() const { return program_; }

  int reused() const { return reused_; }
  int ran() const { return ran_; }
  /// Removes the entries used longest ago beyond kCacheLimitBytes.
  void prune() const { store_.prune(); }

 private:
  /// A digest of the bytes of this program and of `backend`'s plugin, and its library's
  /// version: what changes when the code that runs changes.
  std::string build_identity(const Backend& backend) const;
  ResultCache store_;
  bool fresh_;
  std::string program_;                                 ///< digest of this program's bytes
  mutable std::map<std::string, std::string> plugins_;  ///< per backend name
  mutable std::string every_plugin_;                    ///< the program's and every plugin's digest
  int reused_ = 0, ran_ = 0;
  std::string require_where_, require_why_;  ///< set: a key not kept stops the work
};

}  // namespace bb
