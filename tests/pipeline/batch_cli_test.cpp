// `voltree batch` end to end: the real snakemake running the real voltree binary on tiny studio
// captures (8 photos of 96x96, 3 levels, codebooks of 32). Every asset is built; a second run
// does nothing; a deleted asset is rebuilt alone; a capture whose photos are broken fails alone,
// named with its log; --dry-run prints the planned jobs (also through the example SLURM profile,
// which submits nothing in a dry run); a survey CSV places the trees; and the bad inputs get their messages. Skipped
// when the binary is not built.
#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <string>
#include <unistd.h>
#include <vector>

#include "core/files.h"
#include "voltree_binary.h"

namespace voltree {
namespace {

namespace fs = std::filesystem;
using test::Outcome;
using test::Voltree;
using test::VoltreeCaptured;

const std::vector<std::string> kTrees = {"oak", "pine", "young-oak"};

// Tiny stages, so that the whole suite takes seconds a capture.
constexpr const char* kBatchYaml =
    "options:\n"
    "  reconstruct: \"--levels 3 --no-fit\"\n"
    "  compress: \"--codebook 32 --alpha-codebook 32\"\n"
    "  eval: \"--eval-levels auto --no-plots --no-images --no-input\"\n";

class BatchCli : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    if (!fs::exists(VOLTREE_BINARY)) return;
    captures_ = fs::temp_directory_path() / ("voltree_batch_cli_" + std::to_string(::getpid()));
    fs::remove_all(captures_);
    built_ = true;
    for (const std::string& tree : kTrees)
      built_ = built_ && Voltree("synth --tree " + tree +
                                 " --views 8 --held-out 2 --size 96x96 --supersample 2 --backdrop plain --quiet -o " +
                                 (captures_ / "studio" / tree).string()) == 0;
  }
  static void TearDownTestSuite() {
    if (!captures_.empty()) fs::remove_all(captures_);
  }
  void SetUp() override {
    if (!fs::exists(VOLTREE_BINARY)) GTEST_SKIP() << "build the voltree target first: " << VOLTREE_BINARY;
    ASSERT_TRUE(built_) << "synth failed in " << captures_;
  }
  // A batch root `name` holding copies of the studio captures `trees` and the tiny stage options.
  static fs::path Root(const std::string& name, const std::vector<std::string>& trees) {
    const fs::path root = captures_ / name;
    fs::remove_all(root);
    fs::create_directories(root);
    for (const std::string& tree : trees)
      fs::copy(captures_ / "studio" / tree, root / tree, fs::copy_options::recursive);
    WriteFileAtomic(root / "batch.yaml", kBatchYaml);
    return root;
  }
  static Outcome Batch(const fs::path& root, const std::string& options = "") {
    return VoltreeCaptured("batch '" + root.string() + "' --quiet " + options);
  }
  static std::map<std::string, fs::file_time_type> AssetTimes(const fs::path& root) {
    std::map<std::string, fs::file_time_type> times;
    for (const std::string& tree : kTrees)
      if (fs::exists(root / tree / "tree.vtree")) times[tree] = fs::last_write_time(root / tree / "tree.vtree");
    return times;
  }
  static bool Has(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }
  static fs::path captures_;
  static bool built_;
};
fs::path BatchCli::captures_;
bool BatchCli::built_ = false;

TEST_F(BatchCli, BuildsEveryCaptureResumesAndRebuildsOnlyWhatIsMissing) {
  const fs::path root = Root("three", kTrees);
  fs::create_directories(root / "notes");  // no images/: skipped and named
  const Outcome first = Batch(root, "-j 2");
  ASSERT_EQ(first.status, 0) << first.output;
  for (const std::string& tree : kTrees) {
    EXPECT_TRUE(fs::is_regular_file(root / tree / "tree.vtree")) << tree << "\n" << first.output;
    EXPECT_TRUE(fs::is_regular_file(root / tree / "report" / "metrics.json")) << tree;
    EXPECT_TRUE(fs::is_regular_file(root / tree / "logs" / "reconstruct.tsv")) << tree;
  }
  // The summary: every capture built, with its photos, held-out PSNR and times; the folder named.
  for (const std::string& tree : kTrees) EXPECT_TRUE(Has(first.output, "\n" + tree + " ")) << first.output;
  EXPECT_TRUE(Has(first.output, "8/8")) << first.output;
  EXPECT_TRUE(Has(first.output, " dB")) << first.output;
  EXPECT_TRUE(Has(first.output, "notes      skipped (no images/)")) << first.output;
  EXPECT_FALSE(Has(first.output, "FAILED")) << first.output;
  // The scene of the batch: every asset once, and the renderer draws it.
  const std::string scene = ReadFile(root / "scene.json");
  for (const std::string& tree : kTrees) EXPECT_TRUE(Has(scene, "\"asset\":\"" + tree + "\"")) << scene;
  EXPECT_EQ(Voltree("render '" + (root / "scene.json").string() + "' --orbit 1 --size 64x64 --quiet -o '" +
                    (root / "frames").string() + "' > /dev/null"),
            0);
  // And the web page shows it: the three assets, one instance each.
  const Outcome page =
      VoltreeCaptured("web '" + (root / "scene.json").string() + "' -o '" + (root / "web").string() + "'");
  EXPECT_EQ(page.status, 0) << page.output;
  EXPECT_TRUE(Has(page.output, "3 assets, 3 instances")) << page.output;

  // Again: nothing to do, nothing rewritten.
  const auto built = AssetTimes(root);
  const Outcome second = Batch(root, "-j 2");
  ASSERT_EQ(second.status, 0) << second.output;
  EXPECT_TRUE(Has(second.output, "Nothing to be done")) << second.output;
  EXPECT_EQ(AssetTimes(root), built);

  // One asset deleted: only that one is compressed (and evaluated) again.
  const auto volume_time = fs::last_write_time(root / "pine" / "volume");
  fs::remove(root / "pine" / "tree.vtree");
  const Outcome third = Batch(root, "-j 2");
  ASSERT_EQ(third.status, 0) << third.output;
  ASSERT_TRUE(fs::is_regular_file(root / "pine" / "tree.vtree")) << third.output;
  const auto rebuilt = AssetTimes(root);
  EXPECT_EQ(rebuilt.at("oak"), built.at("oak"));
  EXPECT_EQ(rebuilt.at("young-oak"), built.at("young-oak"));
  EXPECT_NE(rebuilt.at("pine"), built.at("pine"));
  EXPECT_EQ(fs::last_write_time(root / "pine" / "volume"), volume_time) << "the reconstruction was kept";
  // Snakemake's job table: compress, eval and the scene, no reconstruction.
  EXPECT_TRUE(Has(third.output, "\ncompress        1")) << third.output;
  EXPECT_FALSE(Has(third.output, "\nreconstruct ")) << third.output;

  // Surveyed positions: a CSV missing a tree fails the scene alone, named; a full one is used.
  WriteFileAtomic(root / "batch.yaml", std::string(kBatchYaml) + "positions: survey.csv\n");
  WriteFileAtomic(root / "survey.csv", "tree,x,y,rotation\noak,0,0,0\npine,12.5,-3,40\n");
  const Outcome partial = Batch(root);
  EXPECT_NE(partial.status, 0) << partial.output;
  EXPECT_TRUE(Has(partial.output, "scene: failed; log: ")) << partial.output;
  EXPECT_TRUE(Has(ReadFile(root / ".voltree-batch" / "scene.log"), "survey.csv: no row for tree 'young-oak'"));
  EXPECT_EQ(AssetTimes(root), rebuilt);
  WriteFileAtomic(root / "survey.csv", "tree,x,y,rotation\noak,0,0,0\npine,12.5,-3,40\nyoung-oak,-8,6,0\n");
  const Outcome surveyed = Batch(root);
  ASSERT_EQ(surveyed.status, 0) << surveyed.output;
  EXPECT_TRUE(Has(ReadFile(root / "scene.json"), R"({"asset":"pine","position":[12.5,-3.0,0],"rotation":40.0)"))
      << ReadFile(root / "scene.json");
}

TEST_F(BatchCli, ABrokenCaptureFailsAloneAndIsNamedWithItsLog) {
  const fs::path root = Root("broken", {"oak", "pine"});
  // Photos alone (no mattes, no cameras), none of them readable.
  fs::create_directories(root / "broken" / "images");
  for (const char* name : {"a.png", "b.png", "c.jpg"})
    WriteFileAtomic(root / "broken" / "images" / name, "not a photo");
  const Outcome outcome = Batch(root, "-j 2");
  EXPECT_NE(outcome.status, 0) << outcome.output;
  EXPECT_TRUE(fs::is_regular_file(root / "oak" / "tree.vtree")) << outcome.output;
  EXPECT_TRUE(fs::is_regular_file(root / "pine" / "tree.vtree")) << outcome.output;
  EXPECT_FALSE(fs::exists(root / "broken" / "tree.vtree"));
  EXPECT_TRUE(Has(outcome.output, "broken  FAILED (matte)")) << outcome.output;
  const std::string log = (root / "broken" / "logs" / "matte.log").string();
  EXPECT_TRUE(Has(outcome.output, "broken: matte failed; log: " + log)) << outcome.output;
  EXPECT_TRUE(Has(ReadFile(log), "cannot read image")) << ReadFile(log);
  EXPECT_TRUE(Has(outcome.output, "1 of 3 captures failed")) << outcome.output;
  EXPECT_TRUE(Has(outcome.output, "scene: not written")) << outcome.output;
  EXPECT_FALSE(fs::exists(root / "scene.json"));

  // A ROOT holding this batch is resumed: the built captures are kept, the broken one tried again.
  const auto built = AssetTimes(root);
  const Outcome again = Batch(root);
  EXPECT_NE(again.status, 0) << again.output;
  EXPECT_EQ(AssetTimes(root), built);
  EXPECT_TRUE(Has(again.output, "broken  FAILED (matte)")) << again.output;
}

TEST_F(BatchCli, DryRunPrintsThePlannedJobsAndRunsNothing) {
  const fs::path root = Root("dry", kTrees);
  const Outcome outcome = Batch(root, "--dry-run");
  ASSERT_EQ(outcome.status, 0) << outcome.output;
  EXPECT_TRUE(Has(outcome.output, "planned Job stats")) << outcome.output;
  for (const char* rule :
       {"reconstruct        3", "compress           3", "eval               3", "scene              1"})
    EXPECT_TRUE(Has(outcome.output, rule)) << rule << "\n" << outcome.output;
  EXPECT_FALSE(Has(outcome.output, "matte  ")) << "the studio's mattes are kept\n" << outcome.output;
  EXPECT_TRUE(Has(outcome.output, "to do (reconstruct)")) << outcome.output;
  EXPECT_TRUE(AssetTimes(root).empty());
  EXPECT_FALSE(fs::exists(root / "scene.json"));

  // The example SLURM profile plans the same jobs (a dry run submits nothing).
  const Outcome slurm =
      Batch(root, "--dry-run -j 4 --profile '" + std::string(VOLTREE_SOURCE_DIR) + "/workflows/profiles/slurm'");
  ASSERT_EQ(slurm.status, 0) << slurm.output;
  EXPECT_TRUE(Has(slurm.output, "reconstruct        3")) << slurm.output;
  EXPECT_FALSE(fs::exists(root / ".voltree-batch" / "slurm"));
}

// docs/batch.md's direct command: the Snakefile under the real `snakemake -n`, two of the three
// captures chosen by the config, the studio's mattes and cameras kept; nothing is built.
TEST_F(BatchCli, TheDocumentedSnakemakeCommandDryRuns) {
  const fs::path root = Root("direct", kTrees);
  const std::string command = "snakemake -n --snakefile '" + std::string(VOLTREE_SOURCE_DIR) +
                              "/workflows/Snakefile' --directory '" + root.string() +
                              "' -j 2 --config voltree=" + VOLTREE_BINARY + " 'captures=[oak, pine]' 2>&1";
  const auto [status, output] = test::Shell(command);
  EXPECT_EQ(status, 0) << output;
  for (const char* rule :
       {"reconstruct        2", "compress           2", "eval               2", "scene              1"})
    EXPECT_TRUE(Has(output, rule)) << rule << "\n" << output;
  EXPECT_FALSE(Has(output, "\nmatte ")) << output;
  EXPECT_FALSE(Has(output, "\ncalibrate ")) << output;
  EXPECT_FALSE(Has(output, "tree=young-oak")) << output;
  EXPECT_TRUE(Has(output, "This was a dry-run")) << output;
  EXPECT_TRUE(AssetTimes(root).empty());
  EXPECT_FALSE(fs::exists(root / "oak" / "volume"));
}

TEST_F(BatchCli, BadInputGetsAClearMessage) {
  const fs::path empty = Root("empty", {});
  Outcome outcome = Batch(empty);
  EXPECT_NE(outcome.status, 0);
  EXPECT_TRUE(Has(outcome.output, "no captures; expected a folder per tree holding images/")) << outcome.output;

  fs::create_directories(empty / "photos_of_oak");
  outcome = Batch(empty);
  EXPECT_NE(outcome.status, 0);
  EXPECT_TRUE(Has(outcome.output, "without images/: (photos_of_oak)")) << outcome.output;

  const fs::path root = Root("bad", {"oak"});
  outcome = Batch(root, "--profile no-such-profile");
  EXPECT_NE(outcome.status, 0);
  EXPECT_TRUE(Has(outcome.output, "--profile no-such-profile: no such Snakemake profile")) << outcome.output;

  outcome = VoltreeCaptured("batch '" + root.string() + "'", "", "env PATH=/nonexistent ");
  EXPECT_NE(outcome.status, 0);
  EXPECT_TRUE(Has(outcome.output, "'snakemake' is not on PATH")) << outcome.output;

  // A scene.json of the user's, before any batch ran there: refused, untouched.
  WriteFileAtomic(root / "scene.json", "mine");
  outcome = Batch(root);
  EXPECT_NE(outcome.status, 0);
  EXPECT_TRUE(Has(outcome.output, "scene.json: exists and was not written by a batch")) << outcome.output;
  EXPECT_EQ(ReadFile(root / "scene.json"), "mine");
  EXPECT_FALSE(fs::exists(root / "oak" / "tree.vtree"));

  outcome = Batch(captures_ / "no-such-root");
  EXPECT_NE(outcome.status, 0);
  EXPECT_TRUE(Has(outcome.output, "no-such-root: no such folder")) << outcome.output;
  outcome = Batch(root, "-j 0");
  EXPECT_NE(outcome.status, 0);
  EXPECT_TRUE(Has(outcome.output, "-j 0: expected at least 1")) << outcome.output;
}

}  // namespace
}  // namespace voltree
