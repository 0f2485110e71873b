#include "run/child_pool.hpp"

#include <fcntl.h>
#include <poll.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <new>

#include "run/child_batch.hpp"
#include "run/interrupt.hpp"

#if defined(__SANITIZE_ADDRESS__)
#define BB_UNDER_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define BB_UNDER_ASAN 1
#endif
#endif

namespace bb {

namespace {

using Clock = std::chrono::steady_clock;

/// How many shared children a group's queued pieces are spread over, per slot.
constexpr std::size_t kSharesPerSlot = 4;

/// What an interrupt during the runs leaves: outputs are switched into place only after all runs.
constexpr const char* kNothingWritten =
    "; nothing more was written and earlier outputs are as they were";

void write_all(int fd, const std::string& bytes) {
  std::size_t at = 0;
  while (at < bytes.size()) {
    const ssize_t n = write(fd, bytes.data() + at, bytes.size() - at);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return;
    at += static_cast<std::size_t>(n);
  }
}

/// The last part of what a child printed, on one line, for a reason.
std::string tail(const std::string& console) {
  std::string t = console.size() > 600 ? "..." + console.substr(console.size() - 600) : console;
  for (char& c : t)
    if (c == '\n' || c == '\r') c = ' ';
  while (!t.empty() && t.back() == ' ') t.pop_back();
  return t;
}

std::string with_console(std::string reason, const std::string& console) {
  const std::string printed = tail(console);
  return printed.empty() ? reason : reason + "; it printed: " + printed;
}

#ifndef BB_UNDER_ASAN
/// This process's address space now (bytes), from /proc/self/statm; 0 if unreadable.
long address_space_bytes() {
  long pages = 0;
  if (std::FILE* f = std::fopen("/proc/self/statm", "r")) {
    if (std::fscanf(f, "%ld", &pages) != 1) pages = 0;
    std::fclose(f);
  }
  return pages * sysconf(_SC_PAGESIZE);
}
#endif

/// Runs first in every child: default signal handlers, its output to `console_fd`, and its
/// memory cap.
void child_setup(int console_fd) {
  restore_default_signal_handlers();
  dup2(console_fd, STDOUT_FILENO);
  dup2(console_fd, STDERR_FILENO);
  close(console_fd);
#ifndef BB_UNDER_ASAN
  // The cap counts from what the child inherited at fork (the parent's results so far),
  // so a backend's room does not depend on which runs came before it.
  const rlim_t cap = static_cast<rlim_t>(address_space_bytes() + kChildMemoryBytes);
  const rlimit memory{cap, cap};
  setrlimit(RLIMIT_AS, &memory);
#endif
}

/// Runs in the child: the work, its bytes to `result_fd`, then out without cleanup.
[[noreturn]] void child_main(const ChildPool::Work& work, int result_fd, int console_fd) {
  child_setup(console_fd);
  int code = 0;
  try {
    write_all(result_fd, work());
  } catch (const std::bad_alloc&) {
    std::fprintf(stderr, "out of memory (a child may use %ld GiB)\n", kChildMemoryBytes >> 30);
    code = 3;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s\n", e.what());
    code = 4;
  }
  std::fflush(nullptr);
  _exit(code);
}

}  // namespace

bool children_memory_capped() {
#ifdef BB_UNDER_ASAN
  return false;
#else
  return true;
#endif
}

struct ChildPool::Active {
  std::vector<Job> jobs;   ///< one, or a group's in the order they run
  std::size_t framed = 0;  ///< a shared child's pieces called back so far
  pid_t pid = -1;
  int result_fd = -1;
  int console_fd = -1;
  Clock::time_point deadline;
  std::string payload;
  std::string console;
  Clock::time_point started;
};

long ChildPool::submit(std::string label, Work work, double timeout, Done done, double priority,
                       std::string group) {
  queue_.push_back({std::move(label), std::move(work), timeout, std::move(done), priority,
                    ++submitted_, std::move(group)});
  return submitted_;
}

void ChildPool::cancel(long number) {
  const auto queued =
      std::find_if(queue_.begin(), queue_.end(), [&](const Job& j) { return j.number == number; });
  if (queued != queue_.end())
    queue_.erase(queued);
  else
    cancelled_.insert(number);
}

int ChildPool::free_slots() const {
  if (!isolated_) return 0;
  return std::max(0, parallel_ - running_ - static_cast<int>(queue_.size()));
}

std::vector<ChildPool::Job> ChildPool::take_next(bool shared) {
  // The first of the highest priority: max_element keeps the first of equals.
  const auto best = std::max_element(queue_.begin(), queue_.end(), [](const Job& a, const Job& b) {
    return a.priority < b.priority;
  });
  std::vector<Job> jobs;
  jobs.push_back(std::move(*best));
  queue_.erase(best);
  if (!shared || jobs.front().group.empty()) return jobs;
  // Its group's other queued pieces, in the order they were queued: all of them with one
  // slot, else a few shares of the queue per slot, so that the last pieces still spread
  // over the slots.
  const std::size_t pieces = queue_.size() + 1;
  const std::size_t shares = parallel_ == 1 ? 1 : kSharesPerSlot * parallel_;
  const std::size_t share = (pieces + shares - 1) / shares;
  for (auto it = queue_.begin(); it != queue_.end() && jobs.size() < share;) {
    if (it->group != jobs.front().group) {
      ++it;
      continue;
    }
    jobs.push_back(std::move(*it));
    it = queue_.erase(it);
  }
  return jobs;
}

void ChildPool::run() {
  if (isolated_)
    run_isolated();
  else
    run_in_process();
}

void ChildPool::run_in_process() {
  while (!queue_.empty()) {
    if (interrupt_signal() != 0)
      throw Interrupted("stopped before " + queue_.front().label + kNothingWritten);
    Job job = std::move(take_next(false).front());
    ChildOutcome outcome;
    try {
      outcome.payload = job.work();
    } catch (const std::exception& e) {
      outcome.kind = ChildOutcome::Kind::Crashed;
      outcome.reason = e.what();
    }
    job.done(outcome);
  }
}

ChildPool::Active ChildPool::start_child(std::vector<Job> jobs) {
  int result[2], console[2];
  if (pipe(result) != 0 || pipe(console) != 0)
    throw std::runtime_error("cannot make a pipe for a child");
  // Nothing buffered here may be printed again by the child.
  std::fflush(nullptr);
  const pid_t parent = getpid();
  const pid_t pid = fork();
  if (pid < 0) throw std::runtime_error("cannot start a child process");
  if (pid == 0) {
    // The child dies with its parent, even a SIGKILLed one; if the parent is already gone
    // (before prctl took effect), it ends at once.
    prctl(PR_SET_PDEATHSIG, SIGKILL);
    if (getppid() != parent) _exit(1);
    close(result[0]);
    close(console[0]);
    if (jobs.size() == 1) child_main(jobs.front().work, result[1], console[1]);
    std::vector<Work> works;
    for (const Job& j : jobs) works.push_back(j.work);
    child_setup(console[1]);
    run_batch_child(works, result[1]);
  }
  close(result[1]);
  close(console[1]);
  Active a;
  // A shared child's limit is its first piece's, renewed as each piece is done.
  a.deadline = Clock::now() + std::chrono::duration_cast<Clock::duration>(
                                  std::chrono::duration<double>(jobs.front().timeout));
  a.jobs = std::move(jobs);
  a.pid = pid;
  a.started = Clock::now();
  a.result_fd = result[0];
  a.console_fd = console[0];
  return a;
}

void ChildPool::deliver_frames(Active& a) {
  if (a.jobs.size() < 2) return;
  while (a.framed < a.jobs.size()) {
    std::optional<ChildFrame> frame = take_frame(a.payload);
    if (!frame) return;
    Job& job = a.jobs[a.framed++];
    if (a.framed < a.jobs.size())
      a.deadline = Clock::now() + std::chrono::duration_cast<Clock::duration>(
                                      std::chrono::duration<double>(a.jobs[a.framed].timeout));
    if (cancelled_.erase(job.number) > 0) continue;
    ChildOutcome outcome;
    outcome.payload = std::move(frame->payload);
    outcome.console = std::move(frame->console);
    outcome.seconds = frame->seconds;
    Done done = std::move(job.done);
    done(outcome);
  }
}

void ChildPool::requeue_rest(Active& a) {
  for (std::size_t k = a.jobs.size(); k-- > a.framed;) {
    Job& job = a.jobs[k];
    if (cancelled_.erase(job.number) > 0) continue;
    job.group.clear();
    queue_.push_front(std::move(job));
  }
}

void ChildPool::read_output(std::vector<Active>& active) {
  // Wait for output, at most until the nearest deadline and never long, to notice signals.
  std::vector<pollfd> fds;
  auto wait = std::chrono::milliseconds(100);
  for (const Active& a : active) {
    if (a.result_fd >= 0) fds.push_back({a.result_fd, POLLIN, 0});
    if (a.console_fd >= 0) fds.push_back({a.console_fd, POLLIN, 0});
    wait = std::min(
        wait, std::chrono::duration_cast<std::chrono::milliseconds>(a.deadline - Clock::now()));
  }
  if (!fds.empty()) poll(fds.data(), fds.size(), static_cast<int>(std::max<long>(wait.count(), 0)));
  char buffer[65536];
  for (Active& a : active)
    for (int* fd : {&a.result_fd, &a.console_fd}) {
      if (*fd < 0) continue;
      pollfd one{*fd, POLLIN, 0};
      if (poll(&one, 1, 0) <= 0) continue;
      const ssize_t n = read(*fd, buffer, sizeof buffer);
      if (n > 0) {
        (fd == &a.result_fd ? a.payload : a.console).append(buffer, static_cast<std::size_t>(n));
      } else if (n == 0 || errno != EINTR) {
        close(*fd);
        *fd = -1;
      }
    }
}

ChildOutcome ChildPool::finish(Active& a, bool closed) {
  ChildOutcome outcome;
  int status = 0;
  if (!closed) {
    kill(a.pid, SIGKILL);
    waitpid(a.pid, &status, 0);
    outcome.kind = ChildOutcome::Kind::Timeout;
    outcome.reason =
        with_console("no result within the time limit of " +
                         std::to_string(a.jobs.front().timeout) + " s (--timeout changes it)",
                     a.console);
    for (int fd : {a.result_fd, a.console_fd})
      if (fd >= 0) close(fd);
  } else {
    waitpid(a.pid, &status, 0);
    if (WIFSIGNALED(status)) {
      outcome.kind = ChildOutcome::Kind::Crashed;
      outcome.reason = with_console("killed by signal " + std::to_string(WTERMSIG(status)) + " (" +
                                        strsignal(WTERMSIG(status)) + ")",
                                    a.console);
    } else if (WEXITSTATUS(status) != 0) {
      outcome.kind = ChildOutcome::Kind::Crashed;
      outcome.reason =
          with_console("exited with code " + std::to_string(WEXITSTATUS(status)), a.console);
    } else {
      outcome.payload = std::move(a.payload);
    }
  }
  outcome.console = std::move(a.console);
  outcome.seconds = std::chrono::duration<double>(Clock::now() - a.started).count();
  return outcome;
}

void ChildPool::run_isolated() {
  std::vector<Active> active;
  const auto stop_all = [&] {
    for (Active& a : active) {
      kill(a.pid, SIGKILL);
      waitpid(a.pid, nullptr, 0);
      if (a.result_fd >= 0) close(a.result_fd);
      if (a.console_fd >= 0) close(a.console_fd);
    }
  };
  // A callback that throws (the work cannot go on) stops the other children first.
  const auto calling_back = [&](const auto& call) {
    try {
      call();
    } catch (...) {
      stop_all();
      queue_.clear();
      throw;
    }
  };
  while (!queue_.empty() || !active.empty()) {
    if (interrupt_signal() != 0) {
      std::string what = queue_.empty() ? "" : queue_.front().label;
      if (!active.empty()) {
        const Active& a = active.front();
        what = a.jobs[std::min(a.framed, a.jobs.size() - 1)].label;
      }
      stop_all();
      queue_.clear();
      throw Interrupted("stopped during " + what + kNothingWritten);
    }
    // The children cancelled by the last callbacks stop before others start (a shared
    // child goes on: its cancelled pieces are not called back).
    std::erase_if(active, [&](Active& a) {
      if (a.jobs.size() != 1 || !cancelled_.erase(a.jobs.front().number)) return false;
      kill(a.pid, SIGKILL);
      waitpid(a.pid, nullptr, 0);
      for (int fd : {a.result_fd, a.console_fd})
        if (fd >= 0) close(fd);
      return true;
    });
    running_ = static_cast<int>(active.size());
    while (static_cast<int>(active.size()) < parallel_ && !queue_.empty())
      active.push_back(start_child(take_next(true)));
    running_ = static_cast<int>(active.size());
    read_output(active);
    for (Active& a : active) calling_back([&] { deliver_frames(a); });
    // Finish every child that closed its output or ran out of time.
    for (std::size_t i = 0; i < active.size();) {
      Active& a = active[i];
      const bool closed = a.result_fd < 0 && a.console_fd < 0;
      if (!closed && Clock::now() < a.deadline) {
        ++i;
        continue;
      }
      if (a.jobs.size() > 1) {
        // A shared child: its pieces not framed (a crash, a hang) run again, one child each.
        finish(a, closed);
        requeue_rest(a);
        active.erase(active.begin() + static_cast<long>(i));
        running_ = static_cast<int>(active.size());
        continue;
      }
      const ChildOutcome outcome = finish(a, closed);
      Done done = std::move(a.jobs.front().done);
      const bool cancelled = cancelled_.erase(a.jobs.front().number) > 0;
      active.erase(active.begin() + static_cast<long>(i));
      running_ = static_cast<int>(active.size());
      if (!cancelled) calling_back([&] { done(outcome); });
    }
  }
}

}  // namespace bb
