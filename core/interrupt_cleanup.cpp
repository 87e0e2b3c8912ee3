#include "core/interrupt_cleanup.h"

#include <cerrno>
#include <csignal>
#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <mutex>
#include <shared_mutex>
#include <string>
#include <thread>
#include <vector>

namespace voltree {
namespace fs = std::filesystem;

namespace {

// The registry: paths being built, guarded by a mutex (only ordinary threads touch it).
struct Registry {
  std::mutex mutex;
  std::vector<fs::path> paths;
};
Registry& TheRegistry() {
  static Registry registry;
  return registry;
}

// Writers hold it shared; the cleanup takes it exclusively and keeps it until the process ends.
std::shared_mutex& TheWriteGate() {
  static std::shared_mutex gate;
  return gate;
}

// The self-pipe: the handler writes the signal number, the watcher thread reads it.
int g_signal_pipe[2] = {-1, -1};

extern "C" void OnTerminatingSignal(int signal_number) {
  const int saved_errno = errno;
  const unsigned char byte = static_cast<unsigned char>(signal_number);
  [[maybe_unused]] const ssize_t written = ::write(g_signal_pipe[1], &byte, 1);
  errno = saved_errno;
}

void RemoveRegisteredAndReraise(int signal_number) {
  // Never released: the writers stay parked until the signal below ends the process.
  static std::unique_lock<std::shared_mutex> no_more_writes;
  no_more_writes = std::unique_lock(TheWriteGate());
  {
    std::lock_guard lock(TheRegistry().mutex);
    for (const fs::path& path : TheRegistry().paths) {
      std::error_code ignored;
      fs::remove_all(path, ignored);
    }
    TheRegistry().paths.clear();
  }
  std::signal(signal_number, SIG_DFL);
  std::raise(signal_number);
}

void WatchSignals() {
  unsigned char byte = 0;
  while (true) {
    const ssize_t got = ::read(g_signal_pipe[0], &byte, 1);
    if (got == 1) RemoveRegisteredAndReraise(byte);
    if (got == 0 || (got < 0 && errno != EINTR)) return;
  }
}

// ".NAME.<tag>-<pid>" -> pid, or 0 when `entry` is not a staging sibling of NAME.
pid_t StagingOwner(const std::string& entry, const std::string& name) {
  for (const char* tag : {".partial-", ".old-", ".tmp-"}) {
    const std::string prefix = "." + name + tag;
    if (!entry.starts_with(prefix)) continue;
    const std::string digits = entry.substr(prefix.size());
    if (digits.empty() || digits.size() > 9 || !std::all_of(digits.begin(), digits.end(), ::isdigit)) return 0;
    return static_cast<pid_t>(std::stol(digits));
  }
  return 0;
}

bool ProcessIsGone(pid_t pid) { return ::kill(pid, 0) != 0 && errno == ESRCH; }

}  // namespace

void InstallInterruptCleanup() {
  if (g_signal_pipe[0] >= 0) return;
  if (::pipe2(g_signal_pipe, O_CLOEXEC) != 0) return;  // no cleanup on signals, but nothing breaks
  std::thread(WatchSignals).detach();
  struct sigaction action {};
  action.sa_handler = OnTerminatingSignal;
  sigemptyset(&action.sa_mask);
  action.sa_flags = SA_RESTART;
  for (int signal_number : {SIGINT, SIGTERM}) {
    struct sigaction previous {};
    // A shell runs background jobs with SIGINT ignored; keep it that way.
    if (::sigaction(signal_number, nullptr, &previous) == 0 && previous.sa_handler == SIG_IGN) continue;
    ::sigaction(signal_number, &action, nullptr);
  }
}

std::shared_lock<std::shared_mutex> HoldOffInterruptCleanup() { return std::shared_lock(TheWriteGate()); }

void RemoveOnInterrupt(const fs::path& path) {
  std::lock_guard lock(TheRegistry().mutex);
  TheRegistry().paths.push_back(path);
}

void ForgetOnInterrupt(const fs::path& path) {
  std::lock_guard lock(TheRegistry().mutex);
  auto& paths = TheRegistry().paths;
  paths.erase(std::remove(paths.begin(), paths.end(), path), paths.end());
}

void RemoveStaleStaging(const fs::path& final_path) {
  const std::string name = final_path.filename().string();
  const fs::path parent = final_path.parent_path().empty() ? fs::path(".") : final_path.parent_path();
  std::error_code error;
  if (name.empty() || !fs::is_directory(parent, error)) return;
  for (const auto& entry : fs::directory_iterator(parent, error)) {
    const pid_t owner = StagingOwner(entry.path().filename().string(), name);
    if (owner > 0 && owner != ::getpid() && ProcessIsGone(owner)) {
      std::error_code ignored;
      fs::remove_all(entry.path(), ignored);
    }
  }
}

}  // namespace voltree
