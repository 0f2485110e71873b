// `report --shard I/N` (or `run --shard I/N`) runs one share of the work and keeps its
// results in a folder; `merge` puts the shards' folders together and writes the report (or
// run's files) from them, refusing shards of other case files, of another build, of another
// command or selection, or a set with one missing.
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include "cli/commands.hpp"
#include "cli/progress.hpp"
#include "files/atomic_file.hpp"
#include "files/result_cache.hpp"
#include "model/text.hpp"
#include "run/build_identity.hpp"
#include "run/stability.hpp"
#include "study/case_error.hpp"

namespace bb::cli {

namespace fs = std::filesystem;

namespace {

/// The file a shard's folder holds beside its kept results.
constexpr const char* kShardManifest = "beachball-shard.txt";

/// What a shard was made from: its place, the build, the command and what it selected, how
/// costs were timed, the cases.
struct ShardManifest {
  Shard shard;
  std::string build;
  ShardOf command = ShardOf::report;
  std::string backends = "all";  ///< run's --backends, comma-separated
  std::string dts = "all";       ///< run's --dt, exact and comma-separated
  std::string cost;              ///< "off", or the cost pass's minimum timed seconds per run
  std::map<std::string, std::string> cases;  ///< name -> digest of its text
};

std::string cost_text(const RunOptions& options) {
  return options.cost ? exact_number(options.cost_options.min_seconds) : "off";
}

std::string backends_text(const RunOptions& options) {
  return options.backends.empty() ? "all" : fmt::format("{}", fmt::join(options.backends, ","));
}

std::string dts_text(const RunOptions& options) {
  std::vector<std::string> dts;
  for (double dt : options.dts) dts.push_back(exact_number(dt));
  return dts.empty() ? "all" : fmt::format("{}", fmt::join(dts, ","));
}

const char* command_name(ShardOf command) {
  return command == ShardOf::run ? "run" : "report";
}

/// The comma-separated words of a manifest's list ("all": none, every one).
std::vector<std::string> listed(const std::string& text) {
  std::vector<std::string> out;
  if (text == "all") return out;
  std::istringstream in(text);
  for (std::string word; std::getline(in, word, ',');) out.push_back(word);
  return out;
}

std::string manifest_text(const ShardManifest& m) {
  std::string out = fmt::format(
      "beachball shard {}/{}\nbuild {}\ncommand {}\nbackends {}\ndt {}\ncost {}\n", m.shard.index,
      m.shard.count, m.build, command_name(m.command), m.backends, m.dts, m.cost);
  for (const auto& [name, text] : m.cases) out += "case " + name + " " + text + "\n";
  return out;
}

ShardManifest read_shard_manifest(const std::string& dir) {
  const std::string path = dir + "/" + kShardManifest;
  std::ifstream in(path);
  if (!in)
    throw CaseError(dir, 0, "is not a shard's folder: it has no " + std::string(kShardManifest));
  ShardManifest m;
  std::string line;
  const auto bad = [&] { return CaseError(path, 0, "is not a shard manifest beachball wrote"); };
  if (!std::getline(in, line) ||
      std::sscanf(line.c_str(), "beachball shard %d/%d", &m.shard.index, &m.shard.count) != 2)
    throw bad();
  while (std::getline(in, line)) {
    std::istringstream words(line);
    std::string what, a, b;
    words >> what >> a >> b;
    if (what == "build")
      m.build = a;
    else if (what == "command" && (a == "run" || a == "report"))
      m.command = a == "run" ? ShardOf::run : ShardOf::report;
    else if (what == "backends")
      m.backends = a;
    else if (what == "dt")
      m.dts = a;
    else if (what == "cost")
      m.cost = a;
    else if (what == "case")
      m.cases[a] = b;
    else
      throw bad();
  }
  return m;
}

std::map<std::string, std::string> case_digests(const std::vector<Scene>& scenes) {
  std::map<std::string, std::string> out;
  for (const Scene& s : scenes) out[s.name] = digest(s.source);
  return out;
}

/// Refuses, before any work, a shard folder that holds anything but kept results and the
/// manifest: a shard never writes among files it did not make.
void check_shard_folder(const std::string& dir) {
  std::error_code ec;
  if (!fs::exists(dir, ec)) return;
  if (!fs::is_directory(dir, ec)) throw CaseError(dir, 0, "is not a folder");
  for (const auto& entry : fs::directory_iterator(dir, ec)) {
    const std::string name = entry.path().filename().string();
    if (name == kShardManifest ||
        (entry.is_regular_file() && name.size() > 32 && name.compare(32, 6, ".entry") == 0))
      continue;
    throw CaseError(dir, 0,
                    "holds " + name +
                        ", which beachball did not write there: a shard's folder holds only "
                        "its kept results (give an empty or new folder)");
  }
}

/// Refuses, before anything is written, a shard holding an entry that is not whole: a merge
/// would otherwise write the cases before it and stop at it.
void check_entries(const std::string& dir) {
  const std::vector<std::string> damaged = ResultCache(dir, 0).damaged_entries();
  if (!damaged.empty())
    throw CaseError(
        dir, 0,
        fmt::format("holds {} kept result(s) that are not whole (cut short or "
                    "damaged), {}{}: run that shard again",
                    damaged.size(), damaged.front(), damaged.size() > 1 ? ", ..." : ""));
}

}  // namespace

int shard_command(const std::vector<std::string>& paths, const std::string& out,
                  const RunOptions& options, ShardOf command) {
  const std::vector<Scene> scenes = load_cases(paths);
  const Registry registry = Registry::load();
  check_before_work(scenes, options);
  check_shard_folder(out);
  say_map_sizes(scenes, options);
  if (const std::string problem = options.cache->store().problem(); !problem.empty())
    throw CaseError(out, 0, "cannot keep the shard's results: " + problem);
  const Shard shard = *options.shard;
  int units = 0;
  for (const Scene& scene : scenes) {
    units += progress_units(scene, registry, options);
    for (const Backend* b : backends_for(scene, registry).all)
      units += backend_runs(options, scene, b->name());
  }
  Progress progress(units);
  RunOptions with_progress = options;
  with_progress.on_progress = [&](const std::string& what) { progress.advance(what); };
  with_progress.on_note = [&](const std::string& text) { progress.note(text); };
  for (const Scene& scene : scenes) {
    const CaseResults results = run_case(scene, registry, with_progress);
    if (command == ShardOf::run) continue;
    // The stability search of the shard's backends (none: no search).
    std::vector<std::string> mine;
    for (const Backend* b : backends_for(scene, registry).all)
      if (backend_runs(options, scene, b->name())) mine.push_back(b->name());
    if (!mine.empty())
      find_stability_all(
          scene, registry, mine, options.jobs,
          [&](const std::string& b) { progress.advance(scene.name + ": stability of " + b); },
          options.isolation, options.timeout, known_trials(results.runs), options.cache);
  }
  const ShardManifest manifest{shard,
                               options.cache->build(),
                               command,
                               backends_text(options),
                               dts_text(options),
                               cost_text(options),
                               case_digests(scenes)};
  write_output_file(out + "/" + kShardManifest, manifest_text(manifest));
  fmt::print("written: {} shard {}/{} of {} cases, its kept results in {}\n", command_name(command),
             shard.index, shard.count, scenes.size(), out);
  return kExitOk;
}

int merge_command(const std::vector<std::string>& shards, const std::vector<std::string>& paths,
                  const std::string& out, const RunOptions& options) {
  const std::vector<Scene> scenes = load_cases(paths);
  const std::map<std::string, std::string> cases = case_digests(scenes);
  // The build is every piece of code this process runs: the plugins (and their engines'
  // libraries) are loaded first.
  const Registry registry = Registry::load();
  const std::string build = build_digest();
  // Every shard of one set, made by this build from these case files: checked before any work.
  std::vector<ShardManifest> manifests;
  std::map<int, std::string> folders;
  for (const std::string& dir : shards) {
    ShardManifest m = read_shard_manifest(dir);
    const ShardManifest& first = manifests.empty() ? m : manifests.front();
    if (m.shard.count != first.shard.count)
      throw CaseError(
          dir, 0,
          fmt::format("is shard {}/{}, of another split than shard {}/{}", m.shard.index,
                      m.shard.count, first.shard.index, first.shard.count));
    if (!folders.emplace(m.shard.index, dir).second)
      throw CaseError(
          dir, 0,
          fmt::format("is shard {}/{}, as another folder given is", m.shard.index, m.shard.count));
    if (m.build != build)
      throw CaseError(dir, 0,
                      "was made by another build of beachball (its program, its libraries or its "
                      "plugins differ): merge with the build that ran the shards");
    if (m.command != first.command || m.backends != first.backends || m.dts != first.dts)
      throw CaseError(dir, 0,
                      fmt::format("is a shard of `{} --backends {} --dt {}`, the first of `{} "
                                  "--backends {} --dt {}`: merge shards of one command",
                                  command_name(m.command), m.backends, m.dts,
                                  command_name(first.command), first.backends, first.dts));
    if (m.cost != first.cost)
      throw CaseError(dir, 0,
                      "timed its costs otherwise than the other shards (--no-cost, "
                      "--cost-time)");
    for (const auto& [name, text] : cases) {
      const auto found = m.cases.find(name);
      if (found == m.cases.end())
        throw CaseError(dir, 0, "has no case " + name + ": give merge the shards' case files");
      if (found->second != text)
        throw CaseError(
            dir, 0,
            "was made from another text of case " + name + ": give merge the shards' case files");
    }
    if (m.cases.size() != cases.size())
      throw CaseError(dir, 0, "was made from more cases than merge was given");
    manifests.push_back(std::move(m));
  }
  if (manifests.empty()) throw CaseError("merge", 0, "give the shards' folders");
  const int count = manifests.front().shard.count;
  for (int i = 1; i <= count; ++i)
    if (!folders.count(i))
      throw CaseError(shards.front(), 0,
                      fmt::format("shard {}/{} is missing: merge needs every shard", i, count));
  for (const auto& [index, dir] : folders) check_entries(dir);
  // The shards' kept results, read where they are: nothing is copied, nothing left behind.
  RunCache kept(folders);
  const ShardManifest& made = manifests.front();
  RunOptions o = options;
  o.cache = &kept;
  o.cost = made.cost != "off";
  if (o.cost) o.cost_options.min_seconds = std::stod(made.cost);
  o.backends = listed(made.backends);
  for (const std::string& dt : listed(made.dts)) o.dts.push_back(std::stod(dt));
  // Every case's results before any file is written: a result no shard holds stops the merge
  // with nothing written.
  const int code = made.command == ShardOf::run ? run_command(paths, out, o, true)
                                                : report_command(paths, out, o);
  fmt::print("merged {} shards: {} results kept by them, {} run here\n", count, kept.reused(),
             kept.ran());
  return code;
}

}  // namespace bb::cli
