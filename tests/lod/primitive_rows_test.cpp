// The bench's primitive rows on meshes that lack leaves or bark: each method builds the part it
// can, the table's notes say which part is missing, and the rows are measured at every size.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "core/progress.h"
#include "lod/lod_bench.h"
#include "lod/synthetic_branches.h"
#include "lod/synthetic_foliage.h"

namespace voltree {
namespace {

LodBenchResult SmallBench(const TreeMesh& mesh, bool save_views = false) {
  LodBenchOptions options;
  options.studio.width = options.studio.height = 32;
  options.studio.held_out = 2;
  options.sizes = {32, 16};
  options.top_views = 0;
  options.preprocess_views = 1;
  options.ellipsoids.max_clusters = 16;
  options.save_views = save_views;
  Progress quiet(true);
  return RunLodBench(mesh, "test", options, quiet);
}

bool Mentions(const LodBenchResult& result, const std::string& text) {
  return std::any_of(result.notes.begin(), result.notes.end(),
                     [&text](const std::string& note) { return note.find(text) != std::string::npos; });
}

TEST(PrimitiveRows, WithoutLeavesBothMethodsDrawTheBranchLinesAndSaySo) {
  const LodBenchResult result = SmallBench(test::SyntheticBranches(false), /*save_views=*/true);
  EXPECT_EQ(result.methods, (std::vector<std::string>{"full", "points", "ellipsoids"}));
  EXPECT_TRUE(Mentions(result, "need leaves"));
  EXPECT_TRUE(Mentions(result, "only branch lines"));
  int rows = 0;
  for (const LodBenchRow& row : result.rows) {
    if (row.method == "full") continue;
    ++rows;
    EXPECT_GT(row.primitives, 0u) << row.method << " " << row.size;
    EXPECT_EQ(row.leaves, 0u);
    EXPECT_EQ(row.level, -1);                                     // no ellipsoid level without leaves
    EXPECT_GT(row.recall, 0.3) << row.method << " " << row.size;  // the lines cover the bark
  }
  EXPECT_EQ(rows, 4);
  // --save-views: the reference and each row's first view at each size, in straight alpha.
  std::vector<std::string> names;
  for (const SavedView& view : result.saved_views) {
    names.push_back(view.name);
    EXPECT_EQ(view.image.height, view.name.ends_with("_32") ? 32 : 16) << view.name;
    EXPECT_EQ(view.image.channels, 4);
  }
  EXPECT_EQ(names, (std::vector<std::string>{"reference_32", "full_32", "points_32", "ellipsoids_32", "reference_16",
                                             "full_16", "points_16", "ellipsoids_16"}));
}

TEST(PrimitiveRows, WithoutBarkBothMethodsDrawTheLeavesPrimitivesAndSaySo) {
  TreeMesh mesh = test::SyntheticFoliage(120, 0.06f);
  mesh.groups.erase(mesh.groups.begin());  // the bark triangle
  const LodBenchResult result = SmallBench(mesh);
  EXPECT_TRUE(Mentions(result, "no bark"));
  for (const LodBenchRow& row : result.rows) {
    if (row.method == "ellipsoids") {
      EXPECT_GT(row.level, 0) << row.size;
      EXPECT_GT(row.primitives, 0u);
      EXPECT_GT(row.recall, 0.0) << row.size;
    }
    if (row.method == "points" && row.size == 16) {
      EXPECT_GT(row.primitives, 0u);  // points, no lines
    }
  }
  EXPECT_FALSE(result.ellipsoid_levels.empty());
  EXPECT_EQ(result.skeleton_segments, 0u);
}

}  // namespace
}  // namespace voltree
