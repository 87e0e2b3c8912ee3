// Resume for `voltree run`: what each finished stage was made from. When a stage finishes, run
// records a fingerprint of its inputs (every file's path, size and modification time) and of its
// options, and one of its outputs, in DIR/.voltree-run/STAGE. The next run skips a stage whose
// outputs are as it wrote them and whose inputs and options are unchanged, so an interrupted run
// picks up where it stopped; an edited input or option redoes that stage and the stages after it
// (their inputs change with it), replacing outputs that run itself wrote.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace voltree {

inline constexpr const char* kRunRecordFolder = ".voltree-run";

// Inputs and outputs are paths relative to the workspace `dir`; a folder counts with every file
// under it, a missing input counts as missing (so its appearing changes the fingerprint).
struct StageRecipe {
  std::string stage;  // "reconstruct", "compress", ...
  std::vector<std::string> inputs;
  std::vector<std::string> outputs;
  std::string options;  // the options that shape the outputs, as canonical text (JSON)
};

std::string StageFingerprint(const std::filesystem::path& dir, const StageRecipe& recipe);
// Every output is as the stage wrote it and the recorded fingerprint equals the present one.
bool StageIsUpToDate(const std::filesystem::path& dir, const StageRecipe& recipe);
// The outputs exist and are exactly what the stage wrote when it was recorded (not a user's
// files, nor edited since), so running the stage again may replace them without --force.
bool StageOwnsOutputs(const std::filesystem::path& dir, const StageRecipe& recipe);
// Records the present fingerprint (after the stage wrote its outputs).
void RecordStage(const std::filesystem::path& dir, const StageRecipe& recipe);
// Forgets a stage's record (before the stage rewrites its outputs, so that an interruption
// never leaves a record that vouches for half of them).
void ForgetStage(const std::filesystem::path& dir, const StageRecipe& recipe);

}  // namespace voltree
