// `voltree demo` through the real binary on a tiny set: the asset is byte-identical whatever the
// staging folder it was built in (the demo works in DIR.partial-<pid> and renames it), and a
// folder that is not a previous demo's is refused without --force.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <unistd.h>

#include "core/files.h"
#include "voltree_binary.h"

namespace voltree {
namespace {

namespace fs = std::filesystem;

using test::Voltree;

class DemoCli : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!fs::exists(VOLTREE_BINARY)) GTEST_SKIP() << "build the voltree target first: " << VOLTREE_BINARY;
    root_ = fs::temp_directory_path() / ("voltree_demo_cli_" + std::to_string(::getpid()));
    fs::remove_all(root_);
    fs::create_directories(root_);
  }
  void TearDown() override { fs::remove_all(root_); }
  fs::path root_;
};

constexpr const char* kTiny =
    " --tree young-oak --views 8 --held-out 2 --size 96x96 --levels 4 --codebook 64 --alpha-codebook 64 --orbit 2 "
    "--orbit-size 64 --quiet > /dev/null";

TEST_F(DemoCli, SameAssetFromAnyStagingFolder) {
  // Two runs in different parents: different process ids, so different staging folders.
  ASSERT_EQ(Voltree("demo -o " + (root_ / "a" / "demo").string() + kTiny), 0);
  ASSERT_EQ(Voltree("demo -o " + (root_ / "b" / "demo").string() + kTiny), 0);
  const std::string first = ReadFile(root_ / "a" / "demo" / "tree.vtree");
  EXPECT_FALSE(first.empty());
  EXPECT_TRUE(first == ReadFile(root_ / "b" / "demo" / "tree.vtree")) << "the assets differ";
  EXPECT_TRUE(fs::exists(root_ / "a" / "demo" / "report" / "index.html"));
  EXPECT_TRUE(fs::exists(root_ / "a" / "demo" / "report" / "orbit" / "frame_001.png"));

  // Run again into the same folder: the previous demo's files are replaced, the user's kept.
  WriteFileAtomic(root_ / "a" / "demo" / "photos" / "p.txt", "keep\n");
  WriteFileAtomic(root_ / "a" / "demo" / "report" / "notes.txt", "mine\n");
  ASSERT_EQ(Voltree("demo -o " + (root_ / "a" / "demo").string() + kTiny), 0);
  EXPECT_EQ(ReadFile(root_ / "a" / "demo" / "photos" / "p.txt"), "keep\n");
  EXPECT_EQ(ReadFile(root_ / "a" / "demo" / "report" / "notes.txt"), "mine\n");
  EXPECT_TRUE(ReadFile(root_ / "a" / "demo" / "tree.vtree") == first);
  EXPECT_TRUE(fs::exists(root_ / "a" / "demo" / ".voltree-demo"));
  for (const auto& entry : fs::recursive_directory_iterator(root_))
    EXPECT_EQ(entry.path().filename().string().find(".partial-"), std::string::npos) << "left: " << entry.path();
}

TEST_F(DemoCli, RefusesAFolderThatIsNotADemo) {
  const fs::path mine = root_ / "mine";
  fs::create_directories(mine);
  WriteFileAtomic(mine / "notes.txt", "keep me\n");
  EXPECT_NE(Voltree("demo -o " + mine.string() + kTiny + " 2>&1"), 0);
  EXPECT_EQ(ReadFile(mine / "notes.txt"), "keep me\n");
  EXPECT_FALSE(fs::exists(mine / "tree.vtree"));
  // A demo.json alone does not make a folder the demo's (issue 14: it used to be replaced).
  WriteFileAtomic(mine / "demo.json", "{}\n");
  EXPECT_NE(Voltree("demo -o " + mine.string() + kTiny + " 2>&1"), 0);
  EXPECT_EQ(ReadFile(mine / "notes.txt"), "keep me\n");
  EXPECT_EQ(ReadFile(mine / "demo.json"), "{}\n");
}

}  // namespace
}  // namespace voltree
