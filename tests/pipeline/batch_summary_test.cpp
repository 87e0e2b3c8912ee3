// The batch summary read back from workspace files: status from the first stage whose output is
// missing (failed when its log exists), Snakemake's benchmark seconds, eval's held-out PSNR; and
// where a Snakemake profile is looked for.
#include "pipeline/batch_summary.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <string>

#include "core/error.h"
#include "core/files.h"
#include "pipeline/batch_captures.h"
#include "pipeline/batch_run.h"

namespace voltree {
namespace {

namespace fs = std::filesystem;

class BatchSummary : public ::testing::Test {
 protected:
  void SetUp() override {
    root_ = fs::temp_directory_path() / ("voltree_batch_summary_" + std::to_string(::getpid()));
    fs::remove_all(root_);
    fs::create_directories(root_);
  }
  void TearDown() override { fs::remove_all(root_); }
  // A capture with the outputs of the stages before `missing` (none missing: all of them).
  fs::path Capture(const std::string& tree, const std::string& missing) {
    const fs::path dir = root_ / tree;
    fs::create_directories(dir / "images");
    fs::create_directories(dir / "truth");
    fs::create_directories(dir / "logs");
    const std::vector<std::pair<std::string, fs::path>> outputs = {
        {"matte", "mattes"}, {"calibrate", "sparse"}, {"reconstruct", "volume"}};
    for (const auto& [stage, output] : outputs) {
      if (stage == missing) return dir;
      fs::create_directories(dir / output);
    }
    if (missing == "compress") return dir;
    WriteFileAtomic(dir / "tree.vtree", std::string(1234, 'x'));
    if (missing == "eval") return dir;
    fs::create_directories(dir / "report");
    WriteFileAtomic(dir / "report" / "metrics.json",
                    R"({"overall": {"held_out": {"rgb_psnr": {"mean": 27.346, "min": 26, "max": 28}}}})");
    return dir;
  }
  fs::path root_;
};

TEST_F(BatchSummary, ABuiltCaptureShowsItsFigures) {
  const fs::path dir = Capture("oak", "");
  WriteFileAtomic(dir / "logs" / "reconstruct.tsv", "s\th:m:s\tmax_rss\n12.3456\t0:00:12\t512.0\n");
  const CaptureSummary summary = SummarizeCapture(root_, "oak", false);
  EXPECT_EQ(summary.status, CaptureStatus::kBuilt);
  ASSERT_TRUE(summary.asset_bytes.has_value());
  EXPECT_EQ(*summary.asset_bytes, 1234u);
  ASSERT_TRUE(summary.held_out_rgb_psnr.has_value());
  EXPECT_DOUBLE_EQ(*summary.held_out_rgb_psnr, 27.346);
  EXPECT_DOUBLE_EQ(summary.stage_seconds.at("reconstruct"), 12.3456);
  const std::string table = FormatBatchSummary({summary});
  EXPECT_NE(table.find("27.35 dB"), std::string::npos) << table;
  EXPECT_NE(table.find("1234"), std::string::npos) << table;
  EXPECT_NE(table.find("12.3"), std::string::npos) << table;
}

TEST_F(BatchSummary, TheFirstMissingOutputWithALogIsTheFailedStage) {
  const fs::path dir = Capture("pine", "reconstruct");
  WriteFileAtomic(dir / "logs" / "reconstruct.log", "voltree: error: ...");
  const CaptureSummary failed = SummarizeCapture(root_, "pine", false);
  EXPECT_EQ(failed.status, CaptureStatus::kFailed);
  EXPECT_EQ(failed.detail, "reconstruct");
  EXPECT_EQ(failed.log, (root_ / "pine" / "logs" / "reconstruct.log").string());
  const std::string table = FormatBatchSummary({failed, SkippedFolder("notes")});
  EXPECT_NE(table.find("FAILED (reconstruct)"), std::string::npos) << table;
  EXPECT_NE(table.find("pine: reconstruct failed; log: " + failed.log), std::string::npos) << table;
  EXPECT_NE(table.find("skipped (no images/)"), std::string::npos) << table;

  Capture("aspen", "compress");  // no log: never ran (a stage before it failed, or the batch stopped)
  EXPECT_EQ(SummarizeCapture(root_, "aspen", false).status, CaptureStatus::kNotRun);
  EXPECT_EQ(SummarizeCapture(root_, "aspen", true).status, CaptureStatus::kPlanned);
}

TEST_F(BatchSummary, EvalIsOnlyNeededWithTruth) {
  const fs::path dir = Capture("birch", "eval");
  EXPECT_EQ(SummarizeCapture(root_, "birch", false).status, CaptureStatus::kNotRun);
  fs::remove_all(dir / "truth");
  EXPECT_EQ(SummarizeCapture(root_, "birch", false).status, CaptureStatus::kBuilt);
}

TEST_F(BatchSummary, CapturesAreTheFoldersWithImages) {
  Capture("oak", "");
  Capture("beech", "");
  fs::create_directories(root_ / "notes");
  fs::create_directories(root_ / ".snakemake");
  WriteFileAtomic(root_ / "positions.csv", "tree,x,y\n");
  const BatchFolders folders = FindBatchCaptures(root_);
  EXPECT_EQ(folders.captures, (std::vector<std::string>{"beech", "oak"}));
  EXPECT_EQ(folders.skipped, (std::vector<std::string>{"notes"}));
}

TEST_F(BatchSummary, ProfilesAreFoldersWithConfigOrNamesUnderHome) {
  const fs::path home = root_ / "home";
  fs::create_directories(home / ".config" / "snakemake" / "slurm");
  WriteFileAtomic(home / ".config" / "snakemake" / "slurm" / "config.yaml", "jobs: 10\n");
  EXPECT_EQ(FindSnakemakeProfile("slurm", home.string()), home / ".config" / "snakemake" / "slurm");
  fs::create_directories(root_ / "mine");
  WriteFileAtomic(root_ / "mine" / "config.yaml", "jobs: 2\n");
  EXPECT_EQ(FindSnakemakeProfile((root_ / "mine").string(), home.string()), root_ / "mine");
  try {
    FindSnakemakeProfile("nowhere", home.string());
    FAIL() << "a missing profile was accepted";
  } catch (const Error& error) {
    EXPECT_NE(std::string(error.what()).find((home / ".config/snakemake/nowhere/config.yaml").string()),
              std::string::npos)
        << error.what();
  }
}

}  // namespace
}  // namespace voltree
