// Ctrl-C (SIGINT) and SIGTERM must not leave half-built outputs behind. Folders being built
// (StagedDirectory's ".X.partial-PID") are registered here; on a signal they are removed, then
// the signal is raised again so the process ends as the signal says (exit status 128 + N).
//
// This is the one piece of process-wide state in voltree, and it is kept tiny: a signal handler
// cannot be handed an object. The handler itself only writes one byte to a pipe (what a handler
// may safely do); a watcher thread reads it and does the removal with ordinary code.
#pragma once

#include <filesystem>
#include <shared_mutex>

namespace voltree {

// Installs the SIGINT/SIGTERM handlers and starts the watcher thread. The app calls it once at
// start; without it, registering is harmless and nothing is removed on a signal.
void InstallInterruptCleanup();

// Registers `path` for removal on a signal while it is being built; Forget it once it is
// committed or removed. Thread-safe.
void RemoveOnInterrupt(const std::filesystem::path& path);
void ForgetOnInterrupt(const std::filesystem::path& path);

// Held by a thread while it creates a file or folder: the cleanup first waits for every write in
// flight and then lets no new one start, so that no worker can recreate a folder it has just
// removed (a frame written a moment after the signal would otherwise be left behind).
[[nodiscard]] std::shared_lock<std::shared_mutex> HoldOffInterruptCleanup();

// A staging sibling's name says which process built it (".X.partial-<pid>", ".X.old-<pid>",
// ".X.tmp-<pid>"); removes those of `final_path` whose process is gone, left by a run that was
// killed outright (SIGKILL, power loss). Folders of live processes are left alone.
void RemoveStaleStaging(const std::filesystem::path& final_path);

}  // namespace voltree
