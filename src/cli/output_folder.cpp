#include "cli/output_folder.hpp"

#include <fcntl.h>
#include <limits.h>
#include <signal.h>
#include <stdio.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>

#include "report/atomic_file.hpp"
#include "report/plots.hpp"
#include "scene/case_error.hpp"

namespace bb::cli {

namespace fs = std::filesystem;

namespace {

/// The pid in a name ending ".tmp.<pid>", or 0.
pid_t temporary_owner(const std::string& name) {
  const auto at = name.rfind(".tmp.");
  if (at == std::string::npos) return 0;
  const std::string digits = name.substr(at + 5);
  if (digits.empty() || digits.find_first_not_of("0123456789") != std::string::npos) return 0;
  return static_cast<pid_t>(std::stol(digits));
}

bool process_gone(pid_t pid) {
  return pid > 0 && kill(pid, 0) != 0 && errno == ESRCH;
}

/// The extensions of the files a report writes.
bool report_file(const fs::path& p) {
  const std::string ext = p.extension().string();
  return ext == ".md" || ext == ".json" || ext == ".csv" || ext == ".svg";
}

/// Every file a case's outputs use.
std::vector<std::string> output_file_names(const Scene& scene) {
  std::vector<std::string> names = plot_file_names(scene);
  for (const char* ext : {".json", ".csv", ".md"}) names.push_back(scene.name + ext);
  return names;
}

}  // namespace

void remove_stale_temporaries(const std::string& folder) {
  std::error_code ec;
  const fs::path dir = fs::absolute(folder, ec);
  for (const auto& entry : fs::directory_iterator(dir, ec))
    if (process_gone(temporary_owner(entry.path().filename().string())))
      fs::remove_all(entry.path(), ec);
  // Staging folders of killed reports sit beside the folder, named <folder>.tmp.<pid>.
  const std::string prefix = dir.filename().string() + ".tmp.";
  for (const auto& entry : fs::directory_iterator(dir.parent_path(), ec)) {
    const std::string name = entry.path().filename().string();
    if (name.rfind(prefix, 0) == 0 && process_gone(temporary_owner(name)))
      fs::remove_all(entry.path(), ec);
  }
}

void check_output_names(const Scene& scene) {
  // The longest temporary suffix: ".plot.tmp." (a plot's working folder) and a pid of up
  // to 7 digits.
  const std::size_t room = NAME_MAX - 17;
  for (const std::string& name : output_file_names(scene))
    if (name.size() > room)
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
  // killed; only a file system without O_TMPFILE gets a named probe.
  const int fd = open(folder.c_str(), O_TMPFILE | O_WRONLY | O_CLOEXEC, 0600);
  if (fd >= 0) {
    close(fd);
    return;
  }
  if (errno != EOPNOTSUPP && errno != EISDIR)
    throw CaseError(folder, 0,
                    std::string("cannot write into the output folder: ") + std::strerror(errno));
  const std::string probe = folder + "/.beachball-probe" + temporary_suffix();
  write_whole_file(probe, "");
  std::remove(probe.c_str());
}

ReportFolder::ReportFolder(std::string out) : out_(std::move(out)) {
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(out_, ec)) {
    if (temporary_owner(entry.path().filename().string()) != 0) continue;
    if (!entry.is_regular_file() || !report_file(entry.path()))
      throw CaseError(out_, 0,
                      "holds '" + entry.path().filename().string() +
                          "', which a report does not write; a report replaces the whole folder, "
                          "so give --out an empty folder or one that holds only a report");
  }
  staging_ = fs::absolute(out_).lexically_normal().string();
  if (!staging_.empty() && staging_.back() == '/') staging_.pop_back();
  staging_ += temporary_suffix();
  fs::remove_all(staging_, ec);
  if (!fs::create_directory(staging_, ec))
    throw CaseError(staging_, 0,
                    "cannot create the folder the new report is built in: " +
                        (ec ? ec.message() : std::string("it exists")));
}

ReportFolder::~ReportFolder() {
  std::error_code ec;
  if (!committed_) fs::remove_all(staging_, ec);
}

void ReportFolder::commit() {
  // One rename swaps the two folders: no moment has a half-old, half-new report.
  if (renameat2(AT_FDCWD, staging_.c_str(), AT_FDCWD, out_.c_str(), RENAME_EXCHANGE) != 0)
    throw WriteError(out_, std::string("cannot switch the new report in: ") + std::strerror(errno));
  committed_ = true;
  std::error_code ec;
  fs::remove_all(staging_, ec);
}

}  // namespace bb::cli
