#include "run/build_identity.hpp"

#include <link.h>

#include <algorithm>
#include <filesystem>
#include <set>

#include "files/file_digest.hpp"
#include "files/result_cache.hpp"
#include "run/outside_plugins.hpp"
#include "run/registry.hpp"

namespace bb {

namespace fs = std::filesystem;

namespace {

/// The real path of `path`, or "" when it does not resolve.
std::string real_path(const std::string& path) {
  std::error_code ec;
  const fs::path real = fs::canonical(path, ec);
  return ec ? "" : real.string();
}

int add_loaded_object(dl_phdr_info* info, std::size_t, void* data) {
  // The program itself has no name here, and the kernel's vDSO no file: both are left out
  // (the program is read as /proc/self/exe).
  if (info->dlpi_name != nullptr && info->dlpi_name[0] == '/')
    static_cast<std::vector<std::string>*>(data)->push_back(info->dlpi_name);
  return 0;
}

/// The real path of the plugin folder, or "".
std::string plugin_folder_path() {
  return real_path(plugin_folder());
}

/// Whether `file` (a real path) is a plugin from outside the tree: its backend's own code.
bool is_outside_plugin(const std::string& file) {
  for (const OutsidePlugin& p : outside_plugins())
    if (p.real == file) return true;
  return false;
}

}  // namespace

std::vector<std::string> loaded_code_files() {
  std::vector<std::string> objects;
  dl_iterate_phdr(add_loaded_object, &objects);
  std::vector<std::string> out = {"/proc/self/exe"};
  std::set<std::string> seen = {real_path("/proc/self/exe")};
  for (const std::string& object : objects)
    if (const std::string real = real_path(object); !real.empty() && seen.insert(real).second)
      out.push_back(real);
  return out;
}

const std::string& shared_code_digest() {
  static const std::string shared = [] {
    const std::string plugins = plugin_folder_path();
    std::vector<std::string> digests;
    for (const std::string& file : loaded_code_files()) {
      if (!plugins.empty() && fs::path(file).parent_path().string() == plugins) continue;
      if (is_outside_plugin(file)) continue;
      const std::string d = file_digest(file);
      // Without the program's own bytes there is no telling builds apart: nothing is kept.
      if (d.empty() && file == "/proc/self/exe") return std::string();
      digests.push_back(d);
    }
    // In a set order: libraries load in an order of their own.
    std::sort(digests.begin(), digests.end());
    std::string all;
    for (const std::string& d : digests) all += d + "\n";
    return digest(all);
  }();
  return shared;
}

std::string plugin_digest(const std::string& backend) {
  if (const OutsidePlugin* outside = outside_plugin(backend)) return file_digest(outside->real);
  return file_digest((fs::path(plugin_folder()) / backend_plugin_file(backend)).string());
}

std::string build_digest() {
  if (shared_code_digest().empty()) return "";
  // In name order: a folder lists its files in no set order.
  std::vector<fs::path> plugins;
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(plugin_folder(), ec))
    plugins.push_back(entry.path());
  std::sort(plugins.begin(), plugins.end());
  std::string all = shared_code_digest() + "\n";
  for (const fs::path& p : plugins)
    all += p.filename().string() + " " + file_digest(p.string()) + "\n";
  // The plugins from outside the tree, by their backends' names: a merge needs the same ones.
  for (const OutsidePlugin& p : outside_plugins())
    all += p.description.variants.front().name + " " + file_digest(p.real) + "\n";
  return digest(all);
}

}  // namespace bb
