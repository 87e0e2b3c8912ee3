// Runs the `colmap` command line as a child process, its output kept in a log file.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace voltree {

// The first executable `name` in the ':'-separated `search_path` (normally $PATH). Throws Error
// naming the program and how to install it (`install_hint`) when there is none.
std::filesystem::path FindExecutable(const std::string& name, const std::string& search_path,
                                     const std::string& install_hint);
// `colmap` from $PATH, or Error saying to `apt-get install colmap`.
std::filesystem::path FindColmap();

struct ChildResult {
  int exit_code = 0;  // meaningful when signal == 0
  int signal = 0;     // non-zero when the child was killed (a crash)
  double seconds = 0;
  bool ok() const { return signal == 0 && exit_code == 0; }
};

// Runs `program args...` with stdin from /dev/null and stdout+stderr appended to `log` (created,
// truncated first). Waits for it. Throws Error only when it cannot be started.
ChildResult RunChild(const std::filesystem::path& program, const std::vector<std::string>& args,
                     const std::filesystem::path& log);

// The last `lines` lines of a log file ("" when it cannot be read).
std::string LogTail(const std::filesystem::path& log, int lines);

// Runs one COLMAP stage (`colmap <stage> args...`, log in `log`) and throws Error with the log's
// tail and path when it fails or crashes.
ChildResult RunColmapStage(const std::filesystem::path& colmap, const std::string& stage,
                           const std::vector<std::string>& args, const std::filesystem::path& log);

}  // namespace voltree
