#include "files/file_batch.hpp"

#include <sys/stat.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <utility>

#include "files/atomic_file.hpp"
#include "files/folder_manifest.hpp"

namespace bb {

namespace fs = std::filesystem;

namespace {

constexpr const char* kJournal = "switch.list";

bool exists_here(const std::string& path) {
  struct stat st {};
  return lstat(path.c_str(), &st) == 0;
}

bool plain_file(const std::string& path) {
  struct stat st {};
  return lstat(path.c_str(), &st) == 0 && S_ISREG(st.st_mode);
}

/// What stops beachball moving `path`, a name its record lists, aside: "" for a plain file
/// or a folder holding only what its own record lists; else the entry it did not write
/// (`path` itself, or a file in it).
std::string not_movable(const std::string& path) {
  std::string foreign;
  if (plain_file(path) || holds_only_recorded_files(path, &foreign)) return "";
  return foreign.empty() ? path : path + "/" + foreign;
}

void check_name(const std::string& name) {
  if (name.empty() || name == "." || name == ".." || name.find('/') != std::string::npos)
    throw WriteError(name, "not a file name");
}

/// One step of a switch: "put" moves the new file in, "drop" moves an old one out.
struct Step {
  bool put = true;
  std::string name;
};

std::string journal_text(const std::vector<Step>& steps) {
  std::string text;
  for (const Step& s : steps) text += (s.put ? "put " : "drop ") + s.name + "\n";
  return text;
}

std::vector<Step> read_journal(const std::string& path) {
  std::vector<Step> steps;
  std::ifstream in(path);
  std::string line;
  while (std::getline(in, line)) {
    if (line.rfind("put ", 0) == 0) steps.push_back({true, line.substr(4)});
    if (line.rfind("drop ", 0) == 0) steps.push_back({false, line.substr(5)});
  }
  return steps;
}

/// The renames done so far, undone in reverse order when a later one fails.
class Renames {
 public:
  void move(const std::string& from, const std::string& to) {
    if (std::rename(from.c_str(), to.c_str()) != 0) throw WriteError(to, os_reason());
    done_.emplace_back(from, to);
  }
  /// Whether every rename was undone.
  bool undo() {
    bool all = true;
    for (auto it = done_.rbegin(); it != done_.rend(); ++it)
      all = std::rename(it->second.c_str(), it->first.c_str()) == 0 && all;
    done_.clear();
    return all;
  }

 private:
  std::vector<std::pair<std::string, std::string>> done_;
};

}  // namespace

FileBatch::FileBatch(std::string folder)
    : folder_(std::move(folder)), staging_(folder_, kStagingPrefix) {
  for (const char* part : {"/new", "/old", "/work"})
    if (mkdir((staging_.path() + part).c_str(), 0700) != 0)
      throw WriteError(staging_.path() + part, os_reason());
}

std::string FileBatch::path_for(const std::string& name) {
  check_name(name);
  if (std::find(puts_.begin(), puts_.end(), name) == puts_.end()) puts_.push_back(name);
  return staging_.path() + "/new/" + name;
}

void FileBatch::write(const std::string& name, const std::string& text) {
  write_whole_file(path_for(name), text);
}

std::string FileBatch::folder_for(const std::string& name) {
  const std::string path = path_for(name);
  if (!folders_.count(name)) {
    if (mkdir(path.c_str(), 0777) != 0) throw WriteError(path, os_reason());
    folders_.insert(name);
  }
  return path;
}

std::string FileBatch::work_folder(const std::string& name) {
  check_name(name);
  const std::string path = staging_.path() + "/work/" + name;
  std::error_code ec;
  fs::remove_all(path, ec);
  if (mkdir(path.c_str(), 0700) != 0) throw WriteError(path, os_reason());
  return path;
}

void FileBatch::drop(const std::string& name) {
  check_name(name);
  drops_.insert(name);
}

void FileBatch::commit() {
  // The folder's record after the switch: what it listed, plus what is put, less what goes.
  std::set<std::string> before = read_manifest(folder_);
  std::set<std::string> after = before;
  before.insert(also_recorded_.begin(), also_recorded_.end());
  std::vector<Step> steps;
  for (const std::string& name : puts_) {
    steps.push_back({true, name});
    after.insert(name);
  }
  for (const std::string& name : drops_)
    if (before.count(name) && std::find(puts_.begin(), puts_.end(), name) == puts_.end()) {
      steps.push_back({false, name});
      after.erase(name);
    }
  // A folder put whole lists what it holds in a record of its own.
  for (const std::string& name : folders_) {
    const std::string path = staging_.path() + "/new/" + name;
    std::set<std::string> files;
    std::error_code ec;
    for (const auto& entry : fs::directory_iterator(path, ec))
      files.insert(entry.path().filename().string());
    if (ec) throw WriteError(path, ec.message());
    write_whole_file(path + "/" + kManifestName, manifest_text(files));
  }
  // The record goes last: until it is in place, the old one still describes the folder.
  write_whole_file(staging_.path() + "/new/" + kManifestName, manifest_text(after));
  steps.push_back({true, kManifestName});

  // Only files beachball wrote are moved aside: anything else that appeared meanwhile stops
  // the switch before it starts.
  for (const Step& s : steps) {
    const std::string target = folder_ + "/" + s.name;
    if (!exists_here(target)) continue;
    const bool ours = s.name == kManifestName || before.count(s.name);
    const std::string foreign = ours ? not_movable(target) : target;
    if (!foreign.empty())
      throw WriteError(foreign, "it is not a file beachball wrote (it is not in " +
                                    fs::path(foreign).parent_path().string() + "/" + kManifestName +
                                    "); move it away or choose another folder");
  }

  // The journal makes the switch decided: from here a killed process's switch is finished
  // by the next writer of the folder.
  const std::string journal = staging_.path() + "/" + kJournal;
  write_whole_file(journal + ".part", journal_text(steps));
  if (std::rename((journal + ".part").c_str(), journal.c_str()) != 0)
    throw WriteError(journal, os_reason());
  Renames renames;
  try {
    for (const Step& s : steps) {
      const std::string target = folder_ + "/" + s.name;
      if (exists_here(target)) renames.move(target, staging_.path() + "/old/" + s.name);
      if (s.put) renames.move(staging_.path() + "/new/" + s.name, target);
    }
  } catch (const WriteError& e) {
    if (renames.undo()) {
      std::remove(journal.c_str());
      throw;
    }
    // Nothing could be put back either: the journal stays, for the next writer to finish.
    staging_.release();
    throw WriteError(folder_, e.problem() +
                                  "; the files could not be put back either, and the "
                                  "next beachball writing this folder finishes the switch");
  }
  std::remove(journal.c_str());
  // What the switch replaced goes now, before the folder can be moved (a report's is).
  staging_.remove();
}

int finish_interrupted_switches(const std::string& folder) {
  int found = 0;
  std::error_code ec;
  std::vector<fs::path> abandoned;
  for (const auto& entry : fs::directory_iterator(folder, ec)) {
    const std::string name = entry.path().filename().string();
    std::error_code kind_error;
    if (name.rfind(kStagingPrefix, 0) == 0 && entry.is_directory(kind_error) &&
        !entry.is_symlink(kind_error) && abandoned_marker((entry.path() / kOwnerMarker).string()))
      abandoned.push_back(entry.path());
  }
  for (const fs::path& staging : abandoned) {
    ++found;
    // A decided switch is finished: each new file still waiting is moved in.
    const std::string journal = (staging / kJournal).string();
    if (plain_file(journal))
      for (const Step& s : read_journal(journal)) {
        if (s.name.empty() || s.name.find('/') != std::string::npos) continue;
        const std::string target = folder + "/" + s.name;
        const std::string waiting = (staging / "new" / s.name).string();
        const std::string aside = (staging / "old" / s.name).string();
        if (s.put && !exists_here(waiting)) continue;
        if (exists_here(target) && !exists_here(aside)) std::rename(target.c_str(), aside.c_str());
        if (s.put) std::rename(waiting.c_str(), target.c_str());
      }
    remove_owned_folder(staging.string());
  }
  return found;
}

}  // namespace bb
