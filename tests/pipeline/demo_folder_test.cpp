// The demo's folder: only files a previous demo wrote (and that are still as it wrote them) are
// ever deleted or replaced; a user's files are kept, and a folder without the marker is refused.
#include "pipeline/demo_folder.h"

#include <gtest/gtest.h>

#include <map>

#include "core/error.h"
#include "core/files.h"

namespace voltree {
namespace {
namespace fs = std::filesystem;

class DemoFolder : public ::testing::Test {
 protected:
  void SetUp() override {
    root_ = fs::path(::testing::TempDir()) /
            Str("voltree_demo_folder_", ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(root_);
    fs::create_directories(root_);
  }
  void TearDown() override { fs::remove_all(root_); }
  // A finished demo build with `files` (relative path -> contents).
  fs::path Built(const std::string& name, const std::map<std::string, std::string>& files) {
    const fs::path built = root_ / name;
    for (const auto& [relative, bytes] : files) WriteFileAtomic(built / relative, bytes);
    return built;
  }
  fs::path root_;
};

TEST_F(DemoFolder, FirstInstallRenamesTheBuildAndWritesTheMarker) {
  const fs::path out = root_ / "out";
  InstallDemoFolder(Built("b1", {{"tree.vtree", "asset"}, {"images/a.png", "photo"}}), out, false);
  EXPECT_EQ(ReadFile(out / "tree.vtree"), "asset");
  const auto manifest = ReadDemoManifest(out);
  ASSERT_TRUE(manifest);
  EXPECT_EQ(manifest->files.size(), 2u);
  EXPECT_TRUE(manifest->files.count("images/a.png"));
}

TEST_F(DemoFolder, ReplacesOnlyWhatThePreviousDemoWrote) {
  const fs::path out = root_ / "out";
  InstallDemoFolder(Built("b1", {{"tree.vtree", "old asset"}, {"report/old.png", "old"}, {"images/a.png", "p"}}), out,
                    false);
  WriteFileAtomic(out / "images" / "mine.txt", "keep");  // the user's, beside the demo's
  WriteFileAtomic(out / "notes.txt", "keep too");
  InstallDemoFolder(Built("b2", {{"tree.vtree", "new asset"}, {"images/a.png", "p2"}}), out, false);
  EXPECT_EQ(ReadFile(out / "tree.vtree"), "new asset");
  EXPECT_EQ(ReadFile(out / "images" / "a.png"), "p2");
  EXPECT_FALSE(fs::exists(out / "report")) << "the previous demo's file (and its emptied folder) goes";
  EXPECT_EQ(ReadFile(out / "images" / "mine.txt"), "keep");
  EXPECT_EQ(ReadFile(out / "notes.txt"), "keep too");
  EXPECT_EQ(ReadDemoManifest(out)->files.size(), 2u);
}

TEST_F(DemoFolder, RefusesAFolderWithoutTheMarkerUnlessForced) {
  const fs::path out = root_ / "X";
  WriteFileAtomic(out / "photos" / "p.txt", "keep\n");
  WriteFileAtomic(out / "demo.json", "{}\n");  // looks like a demo's, but the demo did not write it
  EXPECT_THROW(CheckDemoOutput(out, false), Error);
  EXPECT_THROW(InstallDemoFolder(Built("b1", {{"tree.vtree", "a"}}), out, false), Error);
  EXPECT_EQ(ReadFile(out / "demo.json"), "{}\n");
  // --force adds the demo's files beside the user's ...
  InstallDemoFolder(Built("b2", {{"tree.vtree", "a"}}), out, true);
  EXPECT_EQ(ReadFile(out / "tree.vtree"), "a");
  EXPECT_EQ(ReadFile(out / "photos" / "p.txt"), "keep\n");
  // ... but never replaces one of them.
  EXPECT_THROW(InstallDemoFolder(Built("b3", {{"demo.json", "{\"x\": 1}"}}), out, true), Error);
  EXPECT_EQ(ReadFile(out / "demo.json"), "{}\n");
}

TEST_F(DemoFolder, KeepsAFileTheUserChangedSinceTheDemoWroteIt) {
  const fs::path out = root_ / "out";
  InstallDemoFolder(Built("b1", {{"tree.vtree", "a"}, {"report/index.html", "demo's"}}), out, false);
  WriteFileAtomic(out / "report" / "index.html", "edited by the user");
  // The new demo would write it again: refused, nothing changed.
  EXPECT_THROW(InstallDemoFolder(Built("b2", {{"tree.vtree", "b"}, {"report/index.html", "new"}}), out, false), Error);
  EXPECT_EQ(ReadFile(out / "report" / "index.html"), "edited by the user");
  EXPECT_EQ(ReadFile(out / "tree.vtree"), "a");
  // A new demo that does not write it leaves it in place.
  InstallDemoFolder(Built("b3", {{"tree.vtree", "c"}}), out, false);
  EXPECT_EQ(ReadFile(out / "report" / "index.html"), "edited by the user");
}

TEST_F(DemoFolder, RefusesAMarkerThatPointsOutsideTheFolder) {
  const fs::path out = root_ / "out";
  WriteFileAtomic(out / kDemoMarker, R"({"files": {"../victim.txt": 0}})");
  EXPECT_THROW(ReadDemoManifest(out), Error);
  WriteFileAtomic(out / kDemoMarker, "not json");
  EXPECT_THROW(ReadDemoManifest(out), Error);
}

}  // namespace
}  // namespace voltree
