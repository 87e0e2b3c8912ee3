#include "capture/colmap_runner.h"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>

#include "core/error.h"

extern char** environ;

namespace voltree {
namespace fs = std::filesystem;

fs::path FindExecutable(const std::string& name, const std::string& search_path, const std::string& install_hint) {
  std::stringstream folders(search_path);
  std::string folder;
  while (std::getline(folders, folder, ':')) {
    if (folder.empty()) continue;
    const fs::path candidate = fs::path(folder) / name;
    if (::access(candidate.c_str(), X_OK) == 0 && fs::is_regular_file(candidate)) return candidate;
  }
  Fail("'", name, "' is not on PATH; install it (", install_hint, ")");
}

fs::path FindColmap() {
  const char* path = std::getenv("PATH");
  return FindExecutable("colmap", path ? path : "", "apt-get install colmap");
}

ChildResult RunChild(const fs::path& program, const std::vector<std::string>& args, const fs::path& log) {
  if (!log.parent_path().empty()) fs::create_directories(log.parent_path());
  std::vector<std::string> argv_strings = {program.string()};
  argv_strings.insert(argv_strings.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (std::string& arg : argv_strings) argv.push_back(arg.data());
  argv.push_back(nullptr);

  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_adddup2(&actions, STDOUT_FILENO, STDERR_FILENO);

  const auto start = std::chrono::steady_clock::now();
  pid_t pid = 0;
  const int spawn_error = posix_spawn(&pid, program.c_str(), &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (spawn_error != 0) Fail("cannot start ", program.string(), ": ", std::strerror(spawn_error));

  int status = 0;
  while (::waitpid(pid, &status, 0) < 0) {
    if (errno != EINTR) Fail("waiting for ", program.string(), " failed: ", std::strerror(errno));
  }
  ChildResult result;
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (WIFSIGNALED(status))
    result.signal = WTERMSIG(status);
  else if (WIFEXITED(status))
    result.exit_code = WEXITSTATUS(status);
  return result;
}

std::string LogTail(const fs::path& log, int lines) {
  std::ifstream in(log, std::ios::binary);
  if (!in) return "";
  std::vector<std::string> all;
  std::string line;
  while (std::getline(in, line)) all.push_back(line);
  const size_t first = all.size() > size_t(lines) ? all.size() - size_t(lines) : 0;
  std::string tail;
  for (size_t i = first; i < all.size(); ++i) tail += "  | " + all[i] + "\n";
  return tail;
}

ChildResult RunColmapStage(const fs::path& colmap, const std::string& stage, const std::vector<std::string>& args,
                           const fs::path& log) {
  std::vector<std::string> full = {stage};
  full.insert(full.end(), args.begin(), args.end());
  const ChildResult result = RunChild(colmap, full, log);
  if (!result.ok()) {
    const std::string how = result.signal != 0 ? Str("crashed (signal ", result.signal, ")")
                                               : Str("failed (exit code ", result.exit_code, ")");
    Fail("colmap ", stage, " ", how, "; the end of its log ", log.string(), ":\n", LogTail(log, 15));
  }
  return result;
}

}  // namespace voltree
