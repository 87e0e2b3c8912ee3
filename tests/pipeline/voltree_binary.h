// Runs the built `voltree` binary (VOLTREE_BINARY, set by tests/CMakeLists.txt) with shell
// arguments, for the end-to-end tests of the pipeline commands.
#pragma once

#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace voltree::test {

// The command's exit status as std::system returns it (0 on success).
inline int Voltree(const std::string& arguments) {
  return std::system((std::string(VOLTREE_BINARY) + " " + arguments).c_str());
}

struct Outcome {
  int status = -1;     // the exit status, -1 when killed by a signal
  std::string output;  // stdout and stderr
};

// Runs a shell command, capturing what it prints (stdout; add 2>&1 for stderr).
inline Outcome Shell(const std::string& command) {
  Outcome outcome;
  FILE* pipe = ::popen(command.c_str(), "r");
  if (pipe == nullptr) return outcome;
  std::array<char, 4096> buffer;
  for (size_t n; (n = std::fread(buffer.data(), 1, buffer.size(), pipe)) > 0;) outcome.output.append(buffer.data(), n);
  const int status = ::pclose(pipe);
  outcome.status = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return outcome;
}

// Runs the binary in `cwd` (empty: here) with `prefix` before it (e.g. a command that drops
// privileges), capturing what it prints.
inline Outcome VoltreeCaptured(const std::string& arguments, const std::string& cwd = "",
                               const std::string& prefix = "") {
  return Shell((cwd.empty() ? "" : "cd '" + cwd + "' && ") + prefix + "'" + VOLTREE_BINARY + "' " + arguments +
               " 2>&1");
}

}  // namespace voltree::test
