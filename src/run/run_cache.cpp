#include "run/run_cache.hpp"

#include <algorithm>
#include <bit>
#include <filesystem>
#include <fstream>
#include <vector>

#include "scene/case_error.hpp"

namespace bb {

namespace {

std::string file_digest(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return "";
  return digest(std::string((std::istreambuf_iterator<char>(in)), {}));
}

std::string step_text(std::optional<double> dt) {
  // The step's exact bits: two steps that print alike are still two keys.
  return dt ? std::to_string(std::bit_cast<std::uint64_t>(*dt)) : "own steps";
}

}  // namespace

std::string program_digest() {
  static const std::string digest = file_digest("/proc/self/exe");
  return digest;
}

RunCache::RunCache(const std::string& folder, bool fresh)
    : store_(folder, kCacheLimitBytes), fresh_(fresh), program_(program_digest()) {}

std::string RunCache::build_identity(const Backend& backend) const {
  const std::string name = backend.name();
  auto found = plugins_.find(name);
  if (found == plugins_.end()) {
    const std::string plugin =
        (std::filesystem::path(plugin_folder()) / plugin_file_name(name)).string();
    const auto [library, version] = backend.library_version();
    found = plugins_.emplace(name, file_digest(plugin) + " " + library + " " + version).first;
  }
  return program_ + " " + found->second;
}

std::string RunCache::key(const Scene& scene, const std::string& role, const Backend& backend,
                          std::optional<double> dt) const {
  if (scene.source.empty() || program_.empty()) return "";
  return digest(role + "\n" + backend.name() + "\n" + step_text(dt) + "\n" +
                build_identity(backend) + "\n" + scene.variant + "\n" + scene.source);
}

std::string RunCache::key(const Scene& scene, const std::string& role,
                          const std::string& what) const {
  if (scene.source.empty() || program_.empty()) return "";
  // Every plugin of the build can take part (read once).
  if (every_plugin_.empty()) {
    // In name order: a folder lists its files in no set order.
    std::vector<std::filesystem::path> plugins;
    std::error_code ec;
    for (const auto& entry : std::filesystem::directory_iterator(plugin_folder(), ec))
      plugins.push_back(entry.path());
    std::sort(plugins.begin(), plugins.end());
    every_plugin_ = program_;
    for (const auto& p : plugins)
      every_plugin_ += " " + p.filename().string() + ":" + file_digest(p.string());
  }
  return digest(role + "\n" + what + "\n" + every_plugin_ + "\n" + scene.variant + "\n" +
                scene.source);
}

std::optional<std::string> RunCache::find(const std::string& key) {
  std::optional<std::string> bytes = fresh_ || key.empty() ? std::nullopt : store_.load(key);
  if (!bytes && !key.empty() && !require_why_.empty())
    throw CaseError(require_where_, 0, require_why_);
  ++(bytes ? reused_ : ran_);
  return bytes;
}

std::optional<std::vector<std::string>> RunCache::find_all(const std::vector<std::string>& keys) {
  std::vector<std::string> all;
  for (const std::string& key : keys) {
    std::optional<std::string> bytes = fresh_ || key.empty() ? std::nullopt : store_.load(key);
    if (!bytes) break;
    all.push_back(std::move(*bytes));
  }
  if (all.size() == keys.size()) {
    reused_ += static_cast<int>(keys.size());
    return all;
  }
  for (const std::string& key : keys)
    if (!key.empty() && !require_why_.empty()) throw CaseError(require_where_, 0, require_why_);
  ran_ += static_cast<int>(keys.size());
  return std::nullopt;
}

void RunCache::keep(const std::string& key, const std::string& bytes) const {
  if (!key.empty()) store_.store(key, bytes);
}

bool RunCache::repeatable(const RunRecord& run) {
  return ran_to_end(run.status) || run.status == RunStatus::Diverged ||
         run.status == RunStatus::Unsupported;
}

}  // namespace bb
