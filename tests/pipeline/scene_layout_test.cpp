// Placing a batch's assets: the survey CSV's checks (each error names the file, line and column),
// the grid, and how an asset is named.
#include "pipeline/scene_layout.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <string>

#include "core/error.h"
#include "core/files.h"

namespace voltree {
namespace {

namespace fs = std::filesystem;

fs::path WriteCsv(const std::string& name, const std::string& text) {
  const fs::path path = fs::temp_directory_path() / (name + "_" + std::to_string(::getpid()) + ".csv");
  WriteFileAtomic(path, text);
  return path;
}

std::string CsvError(const std::string& text) {
  const fs::path path = WriteCsv("bad_positions", text);
  std::string message;
  try {
    ReadPositionsCsv(path);
  } catch (const Error& error) {
    message = error.what();
  }
  fs::remove(path);
  return message;
}

TEST(SceneLayout, ReadsASurveyWithColumnsInAnyOrder) {
  const fs::path path = WriteCsv("positions",
                                 "# park survey\nScale, tree, y, x, rotation\n1.5, oak_1, -2, 3.25, 90\n\n"
                                 "1, pine, 4, 0, -15\n");
  const std::vector<ScenePlacement> placements = ReadPositionsCsv(path);
  fs::remove(path);
  ASSERT_EQ(placements.size(), 2u);
  EXPECT_EQ(placements[0].tree, "oak_1");
  EXPECT_DOUBLE_EQ(placements[0].x, 3.25);
  EXPECT_DOUBLE_EQ(placements[0].y, -2);
  EXPECT_DOUBLE_EQ(placements[0].rotation, 90);
  EXPECT_DOUBLE_EQ(placements[0].scale, 1.5);
  EXPECT_EQ(placements[1].tree, "pine");
  EXPECT_DOUBLE_EQ(placements[1].rotation, -15);
}

TEST(SceneLayout, RotationAndScaleAreOptional) {
  const fs::path path = WriteCsv("positions_xy", "tree,x,y\noak,1,2\n");
  const std::vector<ScenePlacement> placements = ReadPositionsCsv(path);
  fs::remove(path);
  ASSERT_EQ(placements.size(), 1u);
  EXPECT_DOUBLE_EQ(placements[0].rotation, 0);
  EXPECT_DOUBLE_EQ(placements[0].scale, 1);
}

TEST(SceneLayout, BadSurveysAreNamedByLineAndColumn) {
  EXPECT_NE(CsvError("tree,x\noak,1\n").find(":1: the header has no column 'y'"), std::string::npos);
  EXPECT_NE(CsvError("tree,x,y,height\n").find(":1: unknown column 'height'"), std::string::npos);
  EXPECT_NE(CsvError("tree,x,y\noak,1,north\n").find(":2: y 'north' is not a number"), std::string::npos);
  EXPECT_NE(CsvError("tree,x,y\noak,1\n").find(":2: 2 fields, but the header names 3"), std::string::npos);
  EXPECT_NE(CsvError("tree,x,y\noak,1,2\noak,3,4\n").find(":3: tree 'oak' has a row already"), std::string::npos);
  EXPECT_NE(CsvError("tree,x,y,scale\noak,1,2,0\n").find(":2: scale 0 must be > 0"), std::string::npos);
  EXPECT_NE(CsvError("").find("empty; expected a header"), std::string::npos);
}

TEST(SceneLayout, TheGridIsSquareAndCentered) {
  const std::vector<ScenePlacement> grid = GridPlacements({"a", "b", "c", "d", "e"}, 10);
  ASSERT_EQ(grid.size(), 5u);  // 3 columns, 2 rows
  EXPECT_DOUBLE_EQ(grid[0].x, -10);
  EXPECT_DOUBLE_EQ(grid[0].y, -5);
  EXPECT_DOUBLE_EQ(grid[2].x, 10);
  EXPECT_DOUBLE_EQ(grid[3].x, -10);
  EXPECT_DOUBLE_EQ(grid[3].y, 5);
  EXPECT_EQ(grid[4].tree, "e");
  const std::vector<ScenePlacement> one = GridPlacements({"alone"}, 10);
  EXPECT_DOUBLE_EQ(one[0].x, 0);
  EXPECT_DOUBLE_EQ(one[0].y, 0);
}

TEST(SceneLayout, AnAssetIsNamedAfterItsCaptureFolder) {
  EXPECT_EQ(AssetNameFromPath("park/oak_17/tree.vtree"), "oak_17");
  EXPECT_EQ(AssetNameFromPath("assets/pine.vtree"), "pine");
}

TEST(SceneLayout, OptionsAreChecked) {
  SceneLayoutOptions options;
  EXPECT_THROW(options.Check(), Error);  // no assets
  const fs::path asset = WriteCsv("not_really_an_asset", "");
  options.assets = {asset};
  options.output = "scene.txt";
  EXPECT_THROW(options.Check(), Error);  // not .json
  options.output = "scene.json";
  EXPECT_NO_THROW(options.Check());
  options.assets = {asset, asset};
  EXPECT_THROW(options.Check(), Error);  // the same name twice
  options.assets = {asset};
  options.spacing = -1;
  EXPECT_THROW(options.Check(), Error);
  fs::remove(asset);
}

}  // namespace
}  // namespace voltree
