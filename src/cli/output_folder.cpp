#include "cli/output_folder.hpp"

#include <fcntl.h>
#include <limits.h>
#include <stdio.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include "cli/commands.hpp"
#include "files/atomic_file.hpp"
#include "files/folder_manifest.hpp"
#include "run/trajectory_names.hpp"
#include "study/case_error.hpp"

namespace bb::cli {

namespace fs = std::filesystem;

namespace {

constexpr const char* kBesidePrefix = ".beachball-report-";

/// A mount point's path as /proc/self/mountinfo writes it: space, tab, newline and
/// backslash as three octal digits after a backslash.
std::string unescape_mountinfo(const std::string& field) {
  std::string out;
  for (std::size_t i = 0; i < field.size(); ++i) {
    if (field[i] == '\\' && i + 3 < field.size()) {
      const std::string digits = field.substr(i + 1, 3);
      if (digits.size() == 3 && digits.find_first_not_of("01234567") == std::string::npos) {
        out += static_cast<char>(std::stoi(digits, nullptr, 8));
        i += 3;
        continue;
      }
    }
    out += field[i];
  }
  return out;
}

/// Whether `path` (canonical) is a mount point: such a folder cannot be renamed.
bool mount_point(const std::string& path) {
  std::ifstream mounts("/proc/self/mountinfo");
  if (mounts) {
    std::string line;
    while (std::getline(mounts, line)) {
      // Fields: id, parent id, major:minor, root, mount point, ...
      std::istringstream fields(line);
      std::string id, parent, device, root, point;
      if (fields >> id >> parent >> device >> root >> point && unescape_mountinfo(point) == path)
        return true;
    }
    return false;
  }
  // Without /proc: a folder on another device than its parent is mounted.
  struct stat self {
  }, parent{};
  return stat(path.c_str(), &self) == 0 &&
         stat(fs::path(path).parent_path().c_str(), &parent) == 0 && self.st_dev != parent.st_dev;
}

/// Whether the current folder is `path` or inside it.
bool holds_current_folder(const std::string& path) {
  std::error_code ec;
  const std::string here = fs::canonical(fs::current_path(ec), ec).string();
  return !ec && (here == path || here.rfind(path + "/", 0) == 0);
}

/// Whether `entry` is one of beachball's own bookkeeping entries: the record, a marker, a
/// temporary folder holding a marker.
bool bookkeeping(const fs::directory_entry& entry) {
  const std::string name = entry.path().filename().string();
  if (name == kManifestName) return true;
  if (name == kOwnerMarker) return true;
  std::error_code ec;
  return name.rfind(kStagingPrefix, 0) == 0 && entry.is_directory(ec) && !entry.is_symlink(ec) &&
         fs::is_regular_file(fs::symlink_status(entry.path() / kOwnerMarker, ec));
}

/// The files of the report in `folder` (listed in its record, or an earlier report's).
std::set<std::string> old_report_files(const std::string& folder) {
  if (has_manifest(folder)) return read_manifest(folder);
  std::set<std::string> names;
  if (!earlier_report(folder)) return names;
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(folder, ec))
    names.insert(entry.path().filename().string());
  return names;
}

/// The first entry of `folder` that beachball did not write, or "".
std::string first_foreign_entry(const std::string& folder) {
  const std::set<std::string> ours = old_report_files(folder);
  std::set<std::string> foreign;
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(folder, ec)) {
    if (bookkeeping(entry)) continue;
    const std::string name = entry.path().filename().string();
    std::error_code kind_error;
    // A folder beachball wrote whole (a case's trajectories) is its own too.
    const bool own_kind =
        !entry.is_symlink(kind_error) &&
        (entry.is_regular_file(kind_error) || holds_only_recorded_files(entry.path().string()));
    if (!ours.count(name) || !own_kind) foreign.insert(name);
  }
  return foreign.empty() ? "" : *foreign.begin();
}

}  // namespace

void check_output_names(const Scene& scene) {
  for (const std::string& name : case_output_names(scene))
    if (name.size() > NAME_MAX)
      throw CaseError(scene.file, 1,
                      "the output file '" + name.substr(0, 60) + "...' would have a name of " +
                          std::to_string(name.size()) + " characters; the file system allows " +
                          std::to_string(NAME_MAX) + " (shorten 'name' or the metric names)");
}

void check_writable(const std::string& folder) {
  std::error_code ec;
  fs::create_directories(folder, ec);
  if (ec) throw CaseError(folder, 0, "cannot create the output folder: " + ec.message());
  // An unnamed file tests the folder and leaves nothing behind, even if this process is
  // killed; a file system without unnamed files is tested by access().
  const int fd = open(folder.c_str(), O_TMPFILE | O_WRONLY | O_CLOEXEC, 0600);
  if (fd >= 0) {
    close(fd);
    return;
  }
  if (errno != EOPNOTSUPP && errno != EISDIR && errno != EINVAL)
    throw CaseError(folder, 0,
                    std::string("cannot write into the output folder: ") + std::strerror(errno));
  if (access(folder.c_str(), W_OK | X_OK) != 0)
    throw CaseError(folder, 0,
                    std::string("cannot write into the output folder: ") + std::strerror(errno));
}

OutputFolder::OutputFolder(const std::string& given) : given_(given) {
  if (given.empty()) throw CaseError("--out", 0, "names no folder");
  struct stat link {
  }, st{};
  if (lstat(given.c_str(), &link) == 0) {
    if (stat(given.c_str(), &st) != 0)
      throw CaseError(given, 0, "is a symbolic link to nothing; point it at a folder or remove it");
    if (!S_ISDIR(st.st_mode)) throw CaseError(given, 0, "is not a folder");
  } else {
    made_ = true;
  }
  try {
    check_writable(given);
    std::error_code ec;
    path_ = fs::canonical(given, ec).string();
    if (ec) throw CaseError(given, 0, "cannot resolve the output folder: " + ec.message());
    // The lock comes before anything in the folder is touched: a second beachball, in this
    // PID namespace or another, stops here.
    lock_ = std::make_unique<FolderLock>(path_);
  } catch (const CaseError&) {
    // A folder refused is not left behind made and empty.
    if (made_) rmdir(given.c_str());
    throw;
  }
  finish_interrupted_switches(path_);
  if (abandoned_marker(path_ + "/" + kOwnerMarker))
    std::remove((path_ + "/" + kOwnerMarker).c_str());
  remove_abandoned_temporaries(fs::path(path_).parent_path().string(), kBesidePrefix);
}

OutputFolder::~OutputFolder() {
  // rmdir removes only an empty folder: anything written there stays.
  if (made_ && !path_.empty()) rmdir(path_.c_str());
}

void check_outputs_are_ours(const std::string& folder, const std::vector<std::string>& names) {
  const std::set<std::string> ours = read_manifest(folder);
  for (const std::string& name : names) {
    const std::string path = folder + "/" + name;
    struct stat st {};
    if (lstat(path.c_str(), &st) != 0) continue;
    if (!ours.count(name) || !S_ISREG(st.st_mode))
      throw CaseError(path, 0,
                      "exists and beachball did not write it (it is not in the folder's " +
                          std::string(kManifestName) +
                          "); beachball replaces only its own files: move it away or choose "
                          "another --out");
  }
}

void check_trajectories_are_ours(const std::string& folder, const std::string& name, bool writing) {
  const std::string own = trajectory_folder_name(name);
  const std::string path = folder + "/" + own;
  struct stat st {};
  if (lstat(path.c_str(), &st) != 0) return;
  const bool recorded = read_manifest(folder).count(own) > 0;
  if (!recorded && !writing) return;
  std::string foreign;
  if (recorded && holds_only_recorded_files(path, &foreign)) return;
  const std::string what = foreign.empty() ? path : path + "/" + foreign;
  const std::string record = (foreign.empty() ? folder : path) + "/" + kManifestName;
  throw CaseError(what, 0,
                  "exists and beachball did not write it (it is not in " + record +
                      "); beachball replaces only its own files: move it away or choose "
                      "another --out");
}

std::vector<std::string> recorded_case_files(const std::string& folder, const std::string& name) {
  std::vector<std::string> out;
  for (const std::string& file : read_manifest(folder))
    if (file == name + ".json" || file == name + ".csv" || file == name + ".md" ||
        (file.rfind(name + "-", 0) == 0 && file.ends_with(".svg")) ||
        file == trajectory_folder_name(name))
      out.push_back(file);
  return out;
}

ReportFolder::ReportFolder(const OutputFolder& out) : out_(out.path()) {
  if (const std::string foreign = first_foreign_entry(out_); !foreign.empty())
    throw CaseError(out.given(), 0,
                    "holds '" + foreign +
                        "', which beachball did not write there; a report replaces the whole "
                        "folder, so give --out an empty folder or one that holds only a report");
  if (mount_point(out_)) {
    by_files_because_ = "it is a mount point";
  } else if (holds_current_folder(out_)) {
    by_files_because_ = "it is the current folder or holds it";
  } else {
    try {
      beside_ =
          std::make_unique<OwnedTemporary>(fs::path(out_).parent_path().string(), kBesidePrefix);
    } catch (const WriteError& e) {
      by_files_because_ = "its parent folder cannot take a new folder (" + e.problem() + ")";
    }
  }
}

ReportFolder::~ReportFolder() = default;

const std::string& ReportFolder::target() const {
  return beside_ ? beside_->path() : out_;
}

void ReportFolder::drop_old_report(FileBatch& batch) const {
  if (beside_) return;
  const std::set<std::string> old = old_report_files(out_);
  batch.treat_as_recorded(old);
  for (const std::string& name : old) batch.drop(name);
}

void ReportFolder::commit() {
  if (!beside_) return;
  const std::string beside = beside_->path();
  // The old folder must still hold only a report: a file the user put there during the
  // runs is not beachball's to remove, so the new report is then switched in file by file.
  std::string why_by_files;
  if (const std::string foreign = first_foreign_entry(out_); !foreign.empty())
    why_by_files = "'" + foreign + "' appeared in it during the runs";
  if (why_by_files.empty()) {
    // The old report takes a marker of its own, so that if this process dies after the
    // exchange, the next run can prove the folder beside is beachball's and remove it.
    const int old_marker = mark_as_owned(out_);
    // The new folder takes the old one's permissions (it was made private, as a temporary).
    if (struct stat st{}; stat(out_.c_str(), &st) == 0) chmod(beside.c_str(), st.st_mode & 07777);
    if (renameat2(AT_FDCWD, beside.c_str(), AT_FDCWD, out_.c_str(), RENAME_EXCHANGE) == 0) {
      std::remove((out_ + "/" + kOwnerMarker).c_str());
      beside_.reset();
      close(old_marker);
      return;
    }
    why_by_files = std::string("the folder cannot be exchanged (") + std::strerror(errno) + ")";
    std::remove((out_ + "/" + kOwnerMarker).c_str());
    close(old_marker);
  }
  // File by file: each new file linked into a batch inside the folder, so the complete new
  // report beside it stays whole until the switch has succeeded.
  try {
    FileBatch batch(out_);
    for (const std::string& name : read_manifest(beside))
      if (link((beside + "/" + name).c_str(), batch.path_for(name).c_str()) != 0)
        throw WriteError(beside + "/" + name, std::strerror(errno));
    const std::set<std::string> old = old_report_files(out_);
    batch.treat_as_recorded(old);
    for (const std::string& name : old) batch.drop(name);
    batch.commit();
  } catch (const WriteError& e) {
    // The finished report is kept where the user can take it.
    const std::string kept = out_ + ".new-" + random_token();
    std::remove((beside + "/" + kOwnerMarker).c_str());
    beside_->release();
    const bool moved = std::rename(beside.c_str(), kept.c_str()) == 0;
    throw WriteError(out_, why_by_files +
                               ", and switching it in file by file failed: " + e.problem() +
                               "; the new report is kept whole in " + (moved ? kept : beside));
  }
}

}  // namespace bb::cli
