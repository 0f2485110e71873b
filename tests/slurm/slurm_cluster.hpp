// A one-node Slurm cluster on localhost for a test: its own munged, slurmctld and slurmd,
// started in a temporary folder on free ports (nothing system-wide touched), stopped by pid
// whatever way the test ends. tests/slurm/slurm_test.cpp runs its jobs on it.
#pragma once

#include <fcntl.h>
#include <gtest/gtest.h>
#include <netinet/in.h>
#include <pwd.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <random>
#include <string>
#include <thread>
#include <vector>

#include "support/missing.hpp"
#include "support/program.hpp"
#include "support/test_support.hpp"

namespace bb::test {

namespace fs = std::filesystem;
using namespace std::chrono_literals;

/// `name` in PATH or in the sbin folders (Debian installs the daemons there, often outside a
/// user's PATH); "" when absent.
inline std::string find_program(const std::string& name) {
  const char* env = std::getenv("PATH");
  std::string dirs = std::string(env ? env : "") + ":/usr/sbin:/sbin:/usr/local/sbin";
  for (std::size_t start = 0; start <= dirs.size();) {
    const std::size_t end = std::min(dirs.find(':', start), dirs.size());
    const fs::path candidate = fs::path(dirs.substr(start, end - start)) / name;
    std::error_code unreadable;  // a folder in PATH we may not look into is skipped
    if (end > start && fs::is_regular_file(candidate, unreadable) &&
        access(candidate.c_str(), X_OK) == 0)
      return candidate.string();
    start = end + 1;
  }
  return "";
}

/// `count` distinct TCP ports on localhost free now: each bound to port 0 (the kernel picks),
/// all held until every one is read, then released for the daemons. Another program could
/// take one in between; the window is the few milliseconds before the daemons start.
inline std::vector<int> free_ports(int count) {
  std::vector<int> sockets, ports;
  for (int i = 0; i < count; ++i) {
    const int s = socket(AF_INET, SOCK_STREAM, 0);
    sockaddr_in address{};
    address.sin_family = AF_INET;
    address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    socklen_t length = sizeof address;
    if (s < 0 || bind(s, reinterpret_cast<sockaddr*>(&address), sizeof address) != 0 ||
        getsockname(s, reinterpret_cast<sockaddr*>(&address), &length) != 0)
      ADD_FAILURE() << "no free port on localhost";
    sockets.push_back(s);
    ports.push_back(ntohs(address.sin_port));
  }
  for (int s : sockets) close(s);
  return ports;
}

/// The daemons this test started, stopped whatever way the test ends: the jobs still queued
/// are cancelled first, then each daemon, the last started first, gets SIGTERM and, if it has
/// not ended after 10 s, SIGKILL. Only these processes are signalled, by their pids. The
/// folder goes too, unless the test failed (its logs and state are then left to read).
class Cluster {
 public:
  explicit Cluster(std::string dir) : dir_(std::move(dir)) {}
  Cluster(const Cluster&) = delete;
  Cluster& operator=(const Cluster&) = delete;

  ~Cluster() {
    if (scancel_ready_) test::shell("timeout 20 scancel --quiet --user=" + user());
    for (auto it = daemons_.rbegin(); it != daemons_.rend(); ++it) stop(it->pid);
    if (!::testing::Test::HasFailure()) {
      std::error_code ignored;
      fs::remove_all(dir_, ignored);
    }
  }

  /// Starts `argv` in the background, its output to DIR/<name>.log; it gets SIGTERM if this
  /// test program dies without stopping it (a killed ctest leaves no daemon behind).
  void start(const std::string& name, const std::vector<std::string>& argv) {
    const std::string log = dir_ + "/" + name + ".log";
    std::vector<char*> args;
    for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
    args.push_back(nullptr);
    const pid_t pid = fork();
    if (pid == 0) {
      prctl(PR_SET_PDEATHSIG, SIGTERM);
      const int fd = open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
      dup2(fd, STDOUT_FILENO);
      dup2(fd, STDERR_FILENO);
      execv(args[0], args.data());
      _exit(127);
    }
    daemons_.push_back({name, log, pid});
  }

  /// The first daemon that has ended, "" while all run.
  std::string ended() {
    for (Daemon& d : daemons_) {
      int status = 0;
      if (d.pid > 0 && waitpid(d.pid, &status, WNOHANG) == d.pid) {
        d.pid = -1;
        return d.name + (WIFEXITED(status)
                             ? " ended with exit code " + std::to_string(WEXITSTATUS(status))
                             : " ended by signal " + std::to_string(WTERMSIG(status)));
      }
      if (d.pid < 0) return d.name + " ended";
    }
    return "";
  }

  /// Every daemon's log, for a failure's message.
  std::string logs() const {
    std::string out;
    for (const Daemon& d : daemons_) out += "\n--- " + d.log + ":\n" + test::bytes(d.log);
    return out;
  }

  /// The cluster is up: jobs may be queued, to cancel at the end.
  void jobs_may_run() { scancel_ready_ = true; }

  static std::string user() {
    const passwd* pw = getpwuid(getuid());
    return pw ? pw->pw_name : std::to_string(getuid());
  }

 private:
  struct Daemon {
    std::string name, log;
    pid_t pid;
  };

  static void stop(pid_t pid) {
    if (pid <= 0) return;
    kill(pid, SIGTERM);
    const auto deadline = std::chrono::steady_clock::now() + 10s;
    while (std::chrono::steady_clock::now() < deadline) {
      if (waitpid(pid, nullptr, WNOHANG) == pid) return;
      std::this_thread::sleep_for(50ms);
    }
    kill(pid, SIGKILL);
    waitpid(pid, nullptr, 0);
  }

  std::string dir_;
  std::vector<Daemon> daemons_;
  bool scancel_ready_ = false;
};

/// The slurm.conf of a one-node cluster in `dir`: no cgroups, no accounting, no MPI, the
/// current user as SlurmUser and SlurmdUser (root or not), munge on its own socket.
///  - config_overrides: slurmd believes slurm.conf, not the hardware. report.sbatch asks 2
///    CPUs a task and the tests submit arrays of 3 tasks: the node has at least 6, so that the
///    tasks run at once, as on a cluster, rather than one after another (on a 2-core machine
///    they share its cores: the test ends sooner for the same work).
///  - MinJobAge=5: a finished job's record is kept 5 s (not 300), so `sbatch --wait` asks
///    every 2 s instead of after 2, 10 and 42 s.
///  - batch_sched_delay=0: a batch job is scheduled at once, not up to 3 s later, so a task
///    starts as the one before it ends.
inline std::string slurm_conf(const std::string& dir, const std::string& socket, int ctld_port,
                              int slurmd_port) {
  std::string conf = R"(ClusterName=beachball
SlurmctldHost=localhost(127.0.0.1)
SlurmctldPort=@ctld_port@
SlurmdPort=@slurmd_port@
SlurmUser=@user@
SlurmdUser=@user@
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=@socket@
StateSaveLocation=@dir@/state
SlurmdSpoolDir=@dir@/spool
SlurmctldPidFile=@dir@/slurmctld.pid
SlurmdPidFile=@dir@/slurmd.pid
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
SwitchType=switch/none
MpiDefault=none
MailProg=/bin/true
ReturnToService=2
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
SlurmdParameters=config_overrides
MinJobAge=5
SchedulerParameters=batch_sched_delay=0
NodeName=localhost NodeAddr=127.0.0.1 CPUs=@cpus@ State=UNKNOWN
PartitionName=debug Nodes=localhost Default=YES MaxTime=INFINITE State=UP
)";
  const std::pair<std::string, std::string> values[] = {
      {"@ctld_port@", std::to_string(ctld_port)},
      {"@slurmd_port@", std::to_string(slurmd_port)},
      {"@user@", Cluster::user()},
      {"@socket@", socket},
      {"@dir@", dir},
      {"@cpus@", std::to_string(std::max(6u, std::thread::hardware_concurrency()))}};
  for (const auto& [key, value] : values)
    for (std::size_t at; (at = conf.find(key)) != std::string::npos;)
      conf.replace(at, key.size(), value);
  return conf;
}

/// A one-node cluster of its own for each test, up before the test's body runs; the test is
/// skipped, saying why, where Slurm is not installed.
class SlurmCluster : public ::testing::Test {
 protected:
  void SetUp() override {
    std::string missing;
    for (const char* name :
         {"munged", "slurmctld", "slurmd", "sbatch", "sinfo", "scancel", "scontrol"}) {
      programs_[name] = find_program(name);
      if (programs_[name].empty()) missing += std::string(" ") + name;
    }
    BB_SKIP_IF_MISSING(missing.empty()
                           ? ""
                           : "no" + missing + " in PATH or /usr/sbin: install Debian's slurm-wlm");

    // A folder of our own: mkdtemp makes it 0700, but munged wants every folder above its
    // socket open to all (execute), and none writable by others.
    dir_ = (fs::path(::testing::TempDir()) / "beachball_slurm_XXXXXX").string();
    ASSERT_NE(mkdtemp(dir_.data()), nullptr) << dir_;
    chmod(dir_.c_str(), 0755);
    for (const char* sub : {"munge", "state", "spool", "work"})
      fs::create_directories(dir_ + "/" + sub);
    cluster_ = std::make_unique<Cluster>(dir_);
    Cluster& cluster = *cluster_;
    const std::string& dir = dir_;
    std::map<std::string, std::string>& programs = programs_;

    // munged with its own key (1 KiB of random bytes, readable by its owner only), socket,
    // pid and seed files, in the foreground so that it stays our child and logs to our file.
    // --force: munged refuses some folders (a world-writable one above ours) that are fine
    // for a test.
    const std::string munge = dir + "/munge", socket = munge + "/socket";
    {
      std::random_device random;
      std::ofstream key(munge + "/munge.key", std::ios::binary);
      for (int i = 0; i < 1024; ++i) key.put(static_cast<char>(random() & 0xff));
    }
    chmod((munge + "/munge.key").c_str(), 0400);
    cluster.start("munged",
                  {programs["munged"], "--foreground", "--force", "--socket=" + socket,
                   "--key-file=" + munge + "/munge.key", "--pid-file=" + munge + "/munged.pid",
                   "--seed-file=" + munge + "/munged.seed"});
    const auto deadline = std::chrono::steady_clock::now() + 60s;
    while (!fs::exists(socket) && cluster.ended().empty() &&
           std::chrono::steady_clock::now() < deadline)
      std::this_thread::sleep_for(100ms);
    ASSERT_TRUE(fs::exists(socket))
        << "munged did not start: " << cluster.ended() << cluster.logs();

    // Every Slurm command here and in the jobs (sbatch passes the environment on) reads this
    // cluster's slurm.conf, and nothing else from a cluster the tests may be running in (a
    // user's SBATCH_PARTITION, say, or the job's own SLURM_JOB_ID).
    std::vector<std::string> inherited;
    for (char** e = environ; *e; ++e) {
      const std::string name = std::string(*e).substr(0, std::string(*e).find('='));
      if (name.rfind("SLURM_", 0) == 0 || name.rfind("SBATCH_", 0) == 0) inherited.push_back(name);
    }
    for (const std::string& name : inherited) unsetenv(name.c_str());
    const std::vector<int> ports = free_ports(2);
    test::write_case(dir, "slurm.conf", slurm_conf(dir, socket, ports[0], ports[1]));
    setenv("SLURM_CONF", (dir + "/slurm.conf").c_str(), 1);
    cluster.start("slurmctld", {programs["slurmctld"], "-D"});
    cluster.start("slurmd", {programs["slurmd"], "-D", "-N", "localhost"});

    // Up when sinfo says the node is idle; a daemon that ends, or 60 s, is a failure.
    std::string state, ended;
    while ((ended = cluster.ended()).empty() && std::chrono::steady_clock::now() < deadline) {
      state = test::shell(programs["sinfo"] + " --noheader --Node --format=%T").out;
      if (state == "idle\n") break;
      std::this_thread::sleep_for(250ms);
    }
    ASSERT_EQ(state, "idle\n") << "the cluster did not start: " << ended << cluster.logs();
    cluster.jobs_may_run();
  }

  void TearDown() override { cluster_.reset(); }

  /// Every daemon's log, for a failure's message.
  std::string logs() const { return cluster_ ? cluster_->logs() : ""; }

  std::string dir_;
  std::map<std::string, std::string> programs_;
  std::unique_ptr<Cluster> cluster_;
};

}  // namespace bb::test
