#include "run/run_cache.hpp"

#include <bit>

#include "model/text.hpp"
#include "run/build_identity.hpp"
#include "study/case_error.hpp"

namespace bb {

namespace {

std::string step_text(std::optional<double> dt) {
  // The step's exact bits: two steps that print alike are still two keys.
  return dt ? std::to_string(std::bit_cast<std::uint64_t>(*dt)) : "own steps";
}

/// Where a shard keeps an outcome that is not repeated every time (a crash, a timeout): for
/// its merge alone, never reused by a run.
std::string once_key(const std::string& key) {
  return digest(key + "\nan outcome kept for a merge");
}

}  // namespace

RunCache::RunCache(const std::string& folder, bool fresh)
    : store_(folder, kCacheLimitBytes), fresh_(fresh) {}

RunCache::RunCache(std::map<int, std::string> shard_folders) : store_("", 0) {
  for (const auto& [index, folder] : shard_folders) shards_.emplace(index, ResultCache(folder, 0));
}

std::string RunCache::build() const {
  return build_digest();
}

void RunCache::describe(const std::string& key, const Scene& scene, std::string run,
                        const std::string& unit) {
  if (shards_.empty() || key.empty()) return;
  Wanted w{scene.name, std::move(run), 0};
  const int count = shards_.rbegin()->first;
  for (int i = 1; !unit.empty() && i <= count && w.shard == 0; ++i)
    if (in_shard(Shard{i, count}, scene, unit)) w.shard = i;
  wanted_[key] = std::move(w);
}

std::string RunCache::key(const Scene& scene, const std::string& role, const Backend& backend,
                          std::optional<double> dt) {
  if (scene.source.empty() || shared_code_digest().empty()) return "";
  const auto [library, version] = backend.library_version();
  const std::string key =
      digest(role + "\n" + backend.name() + "\n" + step_text(dt) + "\n" + shared_code_digest() +
             " " + plugin_digest(backend.name()) + " " + library + " " + version + "\n" +
             scene.variant + "\n" + scene.source);
  // The reference runs in every shard with work in the case; a backend's runs in one.
  const bool reference = role == "reference" || role == "self-check";
  // A cost's role lists its measurements: "cost" says enough.
  const std::string what = role.rfind("cost", 0) == 0 ? "cost" : role;
  describe(key, scene, backend.name() + (dt ? " at dt " + format_dt(*dt) : "") + " (" + what + ")",
           reference ? "" : backend.name());
  return key;
}

std::string RunCache::key(const Scene& scene, const std::string& role, const std::string& what,
                          const std::string& unit) {
  const std::string build = shared_code_digest().empty() ? "" : build_digest();
  if (scene.source.empty() || build.empty()) return "";
  const std::string key =
      digest(role + "\n" + what + "\n" + build + "\n" + scene.variant + "\n" + scene.source);
  describe(key, scene, role + " " + what, unit);
  return key;
}

std::optional<std::string> RunCache::load(const std::string& key) const {
  if (key.empty() || fresh_) return std::nullopt;
  if (shards_.empty()) return store_.load(key);
  for (const std::string& k : {key, once_key(key)})
    for (const auto& [index, shard] : shards_)
      if (auto bytes = shard.load(k)) return bytes;
  return std::nullopt;
}

void RunCache::missing(const std::string& key) const {
  const auto found = wanted_.find(key);
  const Wanted w = found == wanted_.end() ? Wanted{"?", "a run", 0} : found->second;
  const auto shard = shards_.find(w.shard);
  const std::string where =
      shard != shards_.end() ? shard->second.folder() : shards_.begin()->second.folder();
  const std::string which =
      shard != shards_.end()
          ? "shard " + std::to_string(w.shard) + "/" + std::to_string(shards_.rbegin()->first) +
                " runs it, and holds no entry " + key + ".entry"
          : "every shard with work in the case runs it, and none holds an entry " + key + ".entry";
  throw CaseError(where, 0,
                  "case " + w.case_name + ": no shard holds the result of " + w.run + " (" + which +
                      "), though the shards were made from these case files by this build: run "
                      "that shard again");
}

std::optional<std::string> RunCache::peek(const std::string& key) const {
  return load(key);
}

std::optional<std::string> RunCache::find(const std::string& key) {
  std::optional<std::string> bytes = load(key);
  if (!bytes && !key.empty() && !shards_.empty()) missing(key);
  ++(bytes ? reused_ : ran_);
  return bytes;
}

std::optional<std::vector<std::string>> RunCache::find_all(const std::vector<std::string>& keys) {
  std::vector<std::string> all;
  for (const std::string& key : keys) {
    std::optional<std::string> bytes = load(key);
    if (!bytes && !key.empty() && !shards_.empty()) missing(key);
    if (!bytes) break;
    all.push_back(std::move(*bytes));
  }
  if (all.size() == keys.size()) {
    reused_ += static_cast<int>(keys.size());
    return all;
  }
  ran_ += static_cast<int>(keys.size());
  return std::nullopt;
}

void RunCache::keep(const std::string& key, const std::string& bytes, bool repeatable) const {
  if (key.empty()) return;
  if (repeatable)
    store_.store(key, bytes);
  else if (every_outcome_)
    store_.store(once_key(key), bytes);
}

bool RunCache::repeatable(const RunRecord& run) {
  return ran_to_end(run.status) || run.status == RunStatus::Diverged ||
         run.status == RunStatus::Unsupported;
}

}  // namespace bb
