// Results kept between invocations (files/result_cache.hpp), so that only what changed runs
// again. A run's key is made of everything that decides it: the case's text as loaded and
// what was changed in it (a sweep's point), what is kept (an accuracy run, the reference,
// its self-check, a stability trial, a sweep's point; for a run measured against another of
// the same invocation, which one), the backend and its step, and the build: the bytes of the
// program, of every shared library it loaded and of the engine's plugin
// (run/build_identity.hpp). Any edit of a case file reruns that case's runs; a rebuild of any
// of that code reruns what it can change. Only results that another run would repeat are
// kept: a crash or a timeout is run again. A shard keeps those too, apart, for its merge
// alone: the merge gives what the report run whole gives.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "files/result_cache.hpp"
#include "run/registry.hpp"
#include "run/results.hpp"
#include "run/shard.hpp"

namespace bb {

/// The most bytes a cache folder keeps before the entries used longest ago go.
inline constexpr std::uintmax_t kCacheLimitBytes = 1ULL << 30;

class RunCache {
 public:
  /// Kept results in `folder`; with `fresh`, none is reused (new ones are still kept).
  RunCache(const std::string& folder, bool fresh);
  /// A merge's: the kept results of every shard (its folder by its index, 1 to N), read
  /// where they are and never written. A result no shard holds stops the work: find()
  /// throws CaseError naming the shard that runs it, the case and the run.
  explicit RunCache(std::map<int, std::string> shard_folders);
  const std::string& folder() const { return store_.folder(); }
  /// The folder's entries themselves (other kept things share it: a report's drawings).
  const ResultCache& store() const { return store_; }
  /// Whether nothing kept is reused (--fresh).
  bool fresh() const { return fresh_; }
  /// From now on every outcome is kept, a crash or a timeout too, apart from the results
  /// others reuse: a shard's, for its merge.
  void keep_every_outcome() { every_outcome_ = true; }

  /// The key of what `role` keeps of `backend` (a name; the reference's is its own) on
  /// `scene` at `dt` (nullopt for the reference's own steps); "" when the scene has no text
  /// (made in code) or the program cannot be read: such a run is never kept.
  std::string key(const Scene& scene, const std::string& role, const Backend& backend,
                  std::optional<double> dt);
  /// The same for what does not belong to one backend (a sweep's point: `what` names it,
  /// `unit` is its share of a split, shard.hpp).
  std::string key(const Scene& scene, const std::string& role, const std::string& what,
                  const std::string& unit);

  /// The bytes kept under `key` (counted as reused), or nullopt (counted as run; an empty
  /// key, for a run that is never kept, too).
  std::optional<std::string> find(const std::string& key);
  /// The bytes kept under `key`, without counting it: to choose the keys of runs that
  /// depend on it.
  std::optional<std::string> peek(const std::string& key) const;
  /// The bytes of every key, counted as reused, when every one is kept; else nullopt, each
  /// counted as run (runs that belong together: one is reused only with the others).
  std::optional<std::vector<std::string>> find_all(const std::vector<std::string>& keys);
  /// Keeps `bytes` under `key`, when `repeatable` (the same every time it runs) or every
  /// outcome is kept.
  void keep(const std::string& key, const std::string& bytes, bool repeatable) const;

  /// Whether a run with this outcome is the same every time it runs (and so may be kept).
  static bool repeatable(const RunRecord& run);

  /// A digest of the whole build (build_identity.hpp): which build made the kept results.
  std::string build() const;

  /// Counts a run that was not looked for, as run: one that must run to write its steps.
  void count_run(int runs = 1) { ran_ += runs; }

  int reused() const { return reused_; }
  int ran() const { return ran_; }
  /// Removes the entries used longest ago beyond kCacheLimitBytes.
  void prune() const { store_.prune(); }

 private:
  /// The bytes of `key` wherever they are kept (a merge: in any shard, a crash too).
  std::optional<std::string> load(const std::string& key) const;
  /// Throws the merge's CaseError for `key`, which no shard holds.
  [[noreturn]] void missing(const std::string& key) const;
  /// What a key is the key of, for a merge's message.
  struct Wanted {
    std::string case_name, run;
    int shard = 0;  ///< the shard that runs it; 0: every shard with work in the case
  };
  void describe(const std::string& key, const Scene& scene, std::string run,
                const std::string& unit);
  ResultCache store_;
  bool fresh_ = false;
  bool every_outcome_ = false;
  std::map<int, ResultCache> shards_;  ///< a merge's, by index
  std::map<std::string, Wanted> wanted_;
  int reused_ = 0, ran_ = 0;
};

}  // namespace bb
