// Resume records of `voltree run`: a stage is up to date while its inputs, options and outputs
// are as they were when it finished.
#include "pipeline/stage_record.h"

#include <gtest/gtest.h>

#include <thread>

#include "core/error.h"
#include "core/files.h"

namespace voltree {
namespace {
namespace fs = std::filesystem;

TEST(StageRecord, UpToDateUntilAnInputAnOptionOrAnOutputChanges) {
  const fs::path dir = fs::path(::testing::TempDir()) / "voltree_stage_record";
  fs::remove_all(dir);
  WriteFileAtomic(dir / "volume" / "volume.bin", "cells");
  WriteFileAtomic(dir / "volume" / "volume.json", "{}");
  StageRecipe recipe{"compress", {"volume", "scene.json"}, {"tree.vtree"}, R"({"codebook":512})"};
  EXPECT_FALSE(StageIsUpToDate(dir, recipe)) << "never recorded";
  WriteFileAtomic(dir / "tree.vtree", "asset");
  RecordStage(dir, recipe);
  EXPECT_TRUE(StageIsUpToDate(dir, recipe));

  StageRecipe other_options = recipe;
  other_options.options = R"({"codebook":64})";
  EXPECT_FALSE(StageIsUpToDate(dir, other_options));

  WriteFileAtomic(dir / "scene.json", "{}");  // an input that was missing appears
  EXPECT_FALSE(StageIsUpToDate(dir, recipe));
  RecordStage(dir, recipe);
  EXPECT_TRUE(StageIsUpToDate(dir, recipe));

  WriteFileAtomic(dir / "volume" / "volume.bin", "cells, rewritten");  // an input changes
  EXPECT_FALSE(StageIsUpToDate(dir, recipe));
  RecordStage(dir, recipe);
  fs::remove(dir / "tree.vtree");  // an output is gone
  EXPECT_FALSE(StageIsUpToDate(dir, recipe));
  WriteFileAtomic(dir / "tree.vtree", "asset");
  EXPECT_FALSE(StageIsUpToDate(dir, recipe)) << "the output was rewritten: it is not the one recorded";
  EXPECT_FALSE(StageOwnsOutputs(dir, recipe));
  RecordStage(dir, recipe);
  EXPECT_TRUE(StageOwnsOutputs(dir, recipe));
  ForgetStage(dir, recipe);
  EXPECT_FALSE(StageIsUpToDate(dir, recipe));
  EXPECT_FALSE(StageOwnsOutputs(dir, recipe));
  fs::remove_all(dir);
}

}  // namespace
}  // namespace voltree
