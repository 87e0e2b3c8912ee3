#include "pipeline/stage_record.h"

#include <algorithm>
#include <chrono>
#include <utility>

#include "core/crc32.h"
#include "core/error.h"
#include "core/files.h"

namespace voltree {
namespace fs = std::filesystem;

namespace {

// "path size mtime" for a file, one line per file under a folder (sorted), "path missing" else.
std::string Describe(const fs::path& dir, const std::string& relative) {
  const fs::path path = dir / relative;
  auto line = [&](const fs::path& file) {
    const auto stamp = fs::last_write_time(file).time_since_epoch();
    return Str(file.lexically_relative(dir).generic_string(), " ", fs::file_size(file), " ",
               std::chrono::duration_cast<std::chrono::nanoseconds>(stamp).count(), "\n");
  };
  if (fs::is_regular_file(path)) return line(path);
  if (!fs::is_directory(path)) return relative + " missing\n";
  std::vector<std::string> lines;
  for (const auto& entry : fs::recursive_directory_iterator(path))
    if (entry.is_regular_file()) lines.push_back(line(entry.path()));
  std::sort(lines.begin(), lines.end());
  std::string text;
  for (const std::string& each : lines) text += each;
  return text;
}

fs::path RecordPath(const fs::path& dir, const StageRecipe& recipe) { return dir / kRunRecordFolder / recipe.stage; }

}  // namespace

std::string StageFingerprint(const fs::path& dir, const StageRecipe& recipe) {
  std::string text = "options " + recipe.options + "\n";
  for (const std::string& input : recipe.inputs) text += Describe(dir, input);
  // The text itself would do; a CRC keeps the record short and readable.
  return Str(recipe.stage, " ", Crc32(text.data(), text.size()), " ", text.size());
}

namespace {

std::string OutputsFingerprint(const fs::path& dir, const StageRecipe& recipe) {
  std::string text;
  for (const std::string& output : recipe.outputs) text += Describe(dir, output);
  return Str("outputs ", Crc32(text.data(), text.size()), " ", text.size());
}

// The record's two lines: the inputs' fingerprint and the outputs'; empty when there is none.
std::pair<std::string, std::string> ReadRecord(const fs::path& dir, const StageRecipe& recipe) {
  const fs::path record = RecordPath(dir, recipe);
  if (!fs::is_regular_file(record)) return {};
  const std::string text = ReadFile(record);
  const size_t newline = text.find('\n');
  if (newline == std::string::npos) return {};
  std::string outputs = text.substr(newline + 1);
  if (!outputs.empty() && outputs.back() == '\n') outputs.pop_back();
  return {text.substr(0, newline), outputs};
}

}  // namespace

bool StageOwnsOutputs(const fs::path& dir, const StageRecipe& recipe) {
  for (const std::string& output : recipe.outputs)
    if (!fs::exists(dir / output)) return false;
  const auto [inputs, outputs] = ReadRecord(dir, recipe);
  return !outputs.empty() && outputs == OutputsFingerprint(dir, recipe);
}

bool StageIsUpToDate(const fs::path& dir, const StageRecipe& recipe) {
  return StageOwnsOutputs(dir, recipe) && ReadRecord(dir, recipe).first == StageFingerprint(dir, recipe);
}

void RecordStage(const fs::path& dir, const StageRecipe& recipe) {
  WriteFileAtomic(RecordPath(dir, recipe),
                  StageFingerprint(dir, recipe) + "\n" + OutputsFingerprint(dir, recipe) + "\n");
}

void ForgetStage(const fs::path& dir, const StageRecipe& recipe) {
  std::error_code ignored;
  fs::remove(RecordPath(dir, recipe), ignored);
}

}  // namespace voltree
