// The bad-input matrix: each case runs the real `voltree` binary on a small prepared folder and
// checks the exit status, the key words of the message (file, field, expected value), that the
// user's files are byte-identical afterwards and that no staging folder (".X.partial-PID") is left.
// README.md's "Reliability" table is generated from kCases; ReadmeTableMatchesTheCases keeps the
// two in sync (it prints the table to paste when they differ).
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/crc32.h"
#include "core/error.h"
#include "core/files.h"
#include "core/image.h"
#include "pipeline/voltree_binary.h"
#include "staging_leftovers.h"

namespace voltree {
namespace {
namespace fs = std::filesystem;

// Root ignores file permissions; as root, permission cases run as the user "nobody".
std::string Unprivileged() { return ::geteuid() == 0 ? "setpriv --reuid=65534 --regid=65534 --clear-groups " : ""; }

test::Outcome RunVoltree(const std::string& arguments, const fs::path& cwd, bool unprivileged = false) {
  return test::VoltreeCaptured(arguments, cwd.string(), unprivileged ? Unprivileged() : "");
}

// A photo with some structure (a dark trunk-like bar on a sky gradient).
Image8 Photo(int width, int height) {
  Image8 photo(width, height, 3);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const bool tree = std::abs(x - width / 2) < width / 8 && y > height / 4;
      photo.at(x, y, 0) = tree ? 60 : uint8_t(120 + y * 80 / height);
      photo.at(x, y, 1) = tree ? 90 : uint8_t(160 + y * 60 / height);
      photo.at(x, y, 2) = tree ? 40 : 230;
    }
  return photo;
}

// PNG chunk: length, type, data, CRC-32 of type and data.
std::string PngChunk(const std::string& type, const std::string& data) {
  auto be32 = [](uint32_t v) { return std::string{char(v >> 24), char(v >> 16), char(v >> 8), char(v)}; };
  const std::string typed = type + data;
  return be32(uint32_t(data.size())) + typed + be32(Crc32(typed.data(), typed.size()));
}

// A 60000 x 60000 RGB PNG of 64 bytes: only the header says how big it is.
std::string DecompressionBombPng() {
  const std::string size = {0, 0, char(0xEA), char(0x60), 0, 0, char(0xEA), char(0x60)};  // 60000, 60000
  const std::string ihdr = size + std::string{8, 2, 0, 0, 0};  // 8-bit RGB, deflate, no filter, no interlace
  const std::string idat = {0x78, 0x01, 0x01, 0x00, 0x00, char(0xFF), char(0xFF)};  // a stored, empty block
  return std::string("\x89PNG\r\n\x1a\n", 8) + PngChunk("IHDR", ihdr) + PngChunk("IDAT", idat) + PngChunk("IEND", "");
}

struct BadInputCase {
  const char* name;                              // what is wrong, as the README table says it
  const char* arguments;                         // voltree's arguments, run in the case's folder
  std::function<void(const fs::path&)> prepare;  // writes the user's files into the case's folder
  int exit_status;
  std::vector<const char*> key_words;  // each must appear in the output
  const char* creates = nullptr;       // a warning case: the one new file it may write
  bool unprivileged = false;           // run as an ordinary user (root may write anywhere)
};

// A tiny demo workspace (about a second): photos, volume/ and a 3-level tree.vtree.
void MakeTinyDemo(const fs::path& folder) {
  const std::string command = Str("'", VOLTREE_BINARY, "' demo --tree young-oak --views 4 --held-out 1 --size 32x32 ",
                                  "--levels 3 --orbit 0 --no-eval --quiet -o '", folder.string(), "' > /dev/null 2>&1");
  if (std::system(command.c_str()) != 0) Fail("the tiny demo failed: ", command);
}

void WritePhotos(const fs::path& images, int count, int width, int height) {
  for (int i = 0; i < count; ++i) WriteImage(images / Str("view_", i, ".png"), Photo(width, height));
}

const std::vector<BadInputCase>& Cases() {
  static const std::vector<BadInputCase> cases = {
      {"a folder with a demo.json that the demo did not write",
       "demo --tree young-oak --views 4 --held-out 1 --size 32x32 --levels 3 --orbit 0 --no-eval --quiet -o X",
       [](const fs::path& d) {
         WriteFileAtomic(d / "X" / "photos" / "p.txt", "keep\n");
         WriteFileAtomic(d / "X" / "demo.json", "{}\n");
       },
       1,
       {"X", "not a previous demo", ".voltree-demo", "--force"}},
      {"a truncated JPEG photo",
       "matte ws --refine none --quiet",
       [](const fs::path& d) {
         WriteImage(d / "ws" / "images" / "a.jpg", Photo(64, 48));
         const std::string bytes = ReadFile(d / "ws" / "images" / "a.jpg");
         WriteFileAtomic(d / "ws" / "images" / "a.jpg", bytes.substr(0, bytes.size() / 2));
       },
       1,
       {"ws/images/a.jpg", "damaged image", "Premature end", "complete file"}},
      {"a 64-byte PNG that declares 60000x60000 pixels",
       "matte ws --refine none --quiet",
       [](const fs::path& d) { WriteFileAtomic(d / "ws" / "images" / "bomb.png", DecompressionBombPng()); },
       1,
       {"ws/images/bomb.png", "60000x60000", "16384x16384"}},
      {"photos of different sizes",
       "matte ws --refine none --quiet",
       [](const fs::path& d) {
         WritePhotos(d / "ws" / "images", 1, 64, 48);
         WriteImage(d / "ws" / "images" / "view_9.png", Photo(48, 40));
       },
       1,
       {"ws/images/view_9.png", "48x40", "64x48", "same size"}},
      {"photos of different sizes, before COLMAP runs",
       "calibrate ws --quiet",
       [](const fs::path& d) {
         WritePhotos(d / "ws" / "images", 3, 64, 48);
         WriteImage(d / "ws" / "images" / "view_9.png", Photo(48, 40));
       },
       1,
       {"ws/images/view_9.png", "48x40", "64x48", "one camera, one size"}},
      {"a 1x1 photo",
       "matte ws --refine none --quiet",
       [](const fs::path& d) { WritePhotos(d / "ws" / "images", 1, 1, 1); },
       1,
       {"ws/images/view_0.png", "1x1", "at least 16x16"}},
      {"an option the library refuses is reported by its flag",
       "reconstruct ws --texels 0 --quiet",
       [](const fs::path& d) { fs::create_directories(d / "ws"); },
       1,
       {"--texels must be in [1, 64], got 0"}},
      {"a nested stage option too",
       "run ws --fit-prior -1 --quiet",
       [](const fs::path& d) { fs::create_directories(d / "ws" / "images"); },
       1,
       {"--fit-prior must be >= 0, got -1"}},
      {"a negative orbit",
       "render tree.vtree --orbit -3 -o frames",
       [](const fs::path& d) { WriteFileAtomic(d / "tree.vtree", "not read\n"); },
       1,
       {"--orbit -3", "1 or more"}},
      {"an orbit of 0 frames",
       "render tree.vtree --orbit 0 -o frames",
       [](const fs::path& d) { WriteFileAtomic(d / "tree.vtree", "not read\n"); },
       1,
       {"--orbit 0", "1 or more"}},
      {"--known-cameras whose image names are not the photos'",
       "calibrate ws --known-cameras model",
       [](const fs::path& d) {
         WritePhotos(d / "ws" / "images", 3, 32, 24);
         WriteFileAtomic(d / "model" / "cameras.txt", "1 PINHOLE 32 24 30 30 16 12\n");
         WriteFileAtomic(d / "model" / "images.txt",
                         "1 1 0 0 0 0 0 5 1 a.png\n\n2 1 0 0 0 0 5 0 1 b.png\n\n3 1 0 0 0 5 0 0 1 c.png\n\n");
         WriteFileAtomic(d / "model" / "points3D.txt", "");
       },
       1,
       {"have a camera in model", "a.png, b.png, c.png", "view_0.png", "expected the model's image names"}},
      {"--level beyond the asset's finest level",
       "render ws/tree.vtree --level 99 -o frames",
       [](const fs::path& d) { MakeTinyDemo(d / "ws"); },
       1,
       {"--level 99", "ws/tree.vtree", "levels 0..2"}},
      {"--level beyond the levels --max-level loads",
       "render ws/tree.vtree --max-level 1 --level 2 -o frames",
       [](const fs::path& d) { MakeTinyDemo(d / "ws"); },
       1,
       {"--level 2", "ws/tree.vtree", "levels 0..1 of its 0..2", "--max-level"}},
      {"an asset of an older format version",
       "info old.vtree",
       [](const fs::path& d) {
         // Format version 1's magic and version: 10-byte billboard records, the atlas last.
         WriteFileAtomic(d / "old.vtree", std::string("VTREE\0\0\0\x01\0\0\0", 12) + std::string(40, 'x'));
       },
       1,
       {"old.vtree", "format version 1", "reads version 2", "must be rebuilt"}},
      {"a codebook larger than the billboards allow (a warning)",
       "compress ws --codebook 65536 -o small.vtree --quiet",
       [](const fs::path& d) { MakeTinyDemo(d / "ws"); },
       0,
       {"warning", "--codebook 65536", "only", "codewords"},
       "small.vtree"},
      {"an asset over --max-bytes even at the smallest codebooks (a warning)",
       "compress ws --max-bytes 1KiB -o small.vtree --quiet",
       [](const fs::path& d) { MakeTinyDemo(d / "ws"); },
       0,
       {"warning", "small.vtree", "over --max-bytes 1024", "fewer --levels"},
       "small.vtree"},
      {"a byte budget that is not a size",
       "compress ws --max-bytes 1MB -o small.vtree --quiet",
       [](const fs::path& d) { MakeTinyDemo(d / "ws"); },
       1,
       {"--max-bytes", "'1MB'", "900KiB"}},
      {"cameras that all stand at one pose",
       "calibrate ws --known-cameras model",
       [](const fs::path& d) {
         WritePhotos(d / "ws" / "images", 3, 32, 24);
         WriteFileAtomic(d / "model" / "cameras.txt", "1 PINHOLE 32 24 30 30 16 12\n");
         std::string images;
         for (int i = 0; i < 3; ++i) images += Str(i + 1, " 1 0 0 0 0 0 5 1 view_", i, ".png\n\n");
         WriteFileAtomic(d / "model" / "images.txt", images);
         WriteFileAtomic(d / "model" / "points3D.txt", "");
       },
       1,
       {"model", "all 3 cameras stand at one position", "expected photos taken from around the tree"}},
      {"--import of a model with a camera whose photo is not in images/",
       "calibrate ws --import M",
       [](const fs::path& d) {
         MakeTinyDemo(d / "ws");
         fs::rename(d / "ws" / "sparse", d / "M");
         for (const char* folder : {"images", "mattes", "foreground"}) fs::remove(d / "ws" / folder / "view_003.png");
       },
       1,
       {"camera for view_003.png", "no matte ws/mattes/view_003.png", "no photo in ws/images", "expected a matte"}},
      {"a workspace you may not write to",
       "matte ws --refine none --quiet",
       [](const fs::path& d) {
         WritePhotos(d / "ws" / "images", 1, 32, 24);
         fs::permissions(d, fs::perms::all);  // the user may enter the case's folder, but not write in ws
         fs::permissions(d / "ws", fs::perms::owner_read | fs::perms::owner_exec | fs::perms::group_read |
                                       fs::perms::group_exec | fs::perms::others_read | fs::perms::others_exec);
       },
       1,
       {"ws/mattes", "Permission denied"},
       nullptr,
       true},
      {"an output folder inside a file",
       "synth --tree young-oak --views 1 --rings 1 --held-out 0 --size 32x32 -o file/out",
       [](const fs::path& d) { WriteFileAtomic(d / "file", "a file, not a folder\n"); },
       1,
       {"file/out", "Not a directory"}},
      {"a scene instance at 1e308",
       "render scene.json --orbit 1 -o frames",
       [](const fs::path& d) {
         WriteFileAtomic(d / "scene.json", R"({"assets": {"oak": "oak.vtree"},)"
                                           R"( "instances": [{"asset": "oak", "position": [1e308, 0, 0]}]})"
                                           "\n");
       },
       1,
       {"scene.json", "instances[0].position", "within +-1e9"}},
      {"scene bounds of 1e-30",
       "reconstruct ws --force --quiet",
       [](const fs::path& d) {
         MakeTinyDemo(d / "ws");
         nlohmann::json scene = nlohmann::json::parse(ReadFile(d / "ws" / "scene.json"));
         scene["bounds_min"] = {1e-30, 1e-30, 1e-30};
         scene["bounds_max"] = {2e-30, 2e-30, 2e-30};
         WriteFileAtomic(d / "ws" / "scene.json", scene.dump(2) + "\n");
       },
       1,
       {"scene bounds", "smaller than one pixel in every view", "scene.json"}},
      {"a mesh with a vertex that is not a number",
       "synth --tree tree.obj --views 1 --rings 1 --held-out 0 --size 32x32 -o out",
       [](const fs::path& d) { WriteFileAtomic(d / "tree.obj", "v 0 0 0\nv 1 0 0\nv 0 nan 1\nf 1 2 3\n"); },
       1,
       {"tree.obj:3", "vertex 3", "'nan'", "not a finite number"}},
  };
  return cases;
}

using Snapshot = std::map<std::string, std::string>;  // relative path -> bytes ("/" for folders)

Snapshot TakeSnapshot(const fs::path& root) {
  Snapshot snapshot;
  for (const auto& entry : fs::recursive_directory_iterator(root)) {
    const std::string relative = entry.path().lexically_relative(root).generic_string();
    snapshot[relative] = entry.is_directory() ? "/" : ReadFile(entry.path());
  }
  return snapshot;
}

using testing::StagingLeftovers;

class BadInput : public ::testing::TestWithParam<size_t> {
 protected:
  void SetUp() override {
    if (!fs::exists(VOLTREE_BINARY)) GTEST_SKIP() << VOLTREE_BINARY << " is not built (build the voltree target)";
    dir_ = fs::temp_directory_path() / Str("voltree_bad_input_", ::getpid(), "_", GetParam());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override {
    if (dir_.empty()) return;
    std::error_code ignored;  // give back what a case took away, so that the folder can be removed
    for (const auto& entry : fs::recursive_directory_iterator(dir_, ignored))
      if (entry.is_directory()) fs::permissions(entry.path(), fs::perms::owner_all, fs::perm_options::add, ignored);
    fs::remove_all(dir_);
  }
  fs::path dir_;
};

TEST_P(BadInput, FailsClearlyAndLeavesTheUsersFilesAlone) {
  const BadInputCase& bad = Cases()[GetParam()];
  bad.prepare(dir_);
  const Snapshot before = TakeSnapshot(dir_);
  const test::Outcome outcome = RunVoltree(bad.arguments, dir_, bad.unprivileged);
  EXPECT_EQ(outcome.status, bad.exit_status) << bad.name << "\n" << outcome.output;
  for (const char* word : bad.key_words)
    EXPECT_NE(outcome.output.find(word), std::string::npos) << bad.name << ": no '" << word << "' in\n"
                                                            << outcome.output;
  EXPECT_EQ(outcome.output.find("internal error"), std::string::npos) << outcome.output;
  EXPECT_EQ(outcome.output.find(".partial-"), std::string::npos) << "names a staging folder: " << outcome.output;
  Snapshot after = TakeSnapshot(dir_);
  if (bad.creates) {
    EXPECT_EQ(after.erase(bad.creates), 1u) << bad.name << ": no " << bad.creates;
  }
  EXPECT_TRUE(after == before) << bad.name << ": the user's files changed";
  EXPECT_TRUE(StagingLeftovers(dir_).empty()) << StagingLeftovers(dir_).front();
}

INSTANTIATE_TEST_SUITE_P(Cases, BadInput, ::testing::Range(size_t(0), Cases().size()),
                         [](const ::testing::TestParamInfo<size_t>& info) { return Str("case_", info.param); });

std::string ReadmeTable() {
  std::string table = "| case | command | the message says |\n|---|---|---|\n";
  for (const BadInputCase& bad : Cases()) {
    std::string words;
    for (const char* word : bad.key_words) words += Str(words.empty() ? "" : ", ", "`", word, "`");
    table += Str("| ", bad.name, " | `voltree ", bad.arguments, "` | exit ", bad.exit_status, "; ", words, " |\n");
  }
  return table;
}

TEST(BadInputTable, ReadmeTableMatchesTheCases) {
  const std::string readme = ReadFile(fs::path(VOLTREE_SOURCE_DIR) / "README.md");
  EXPECT_NE(readme.find(ReadmeTable()), std::string::npos)
      << "README.md's bad-input table is out of date; replace it with:\n"
      << ReadmeTable();
}

// The default codebook size is only the largest the byte budget tries: a volume with fewer
// distinct billboards than that is no news, while the same shortfall of a size asked for is
// (the case above), from every command that compresses.
TEST(CodebookWarning, OnlyForASizeTheUserAskedFor) {
  if (!fs::exists(VOLTREE_BINARY)) GTEST_SKIP() << VOLTREE_BINARY << " is not built (build the voltree target)";
  const fs::path dir = fs::temp_directory_path() / Str("voltree_codebook_warning_", ::getpid());
  fs::remove_all(dir);
  MakeTinyDemo(dir / "ws");
  const test::Outcome by_default = RunVoltree("compress ws -o default.vtree --quiet", dir);
  EXPECT_EQ(by_default.status, 0) << by_default.output;
  EXPECT_EQ(by_default.output.find("warning"), std::string::npos) << by_default.output;
  const test::Outcome asked = RunVoltree("compress ws --alpha-codebook 4096 -o asked.vtree --quiet", dir);
  EXPECT_EQ(asked.status, 0) << asked.output;
  EXPECT_NE(asked.output.find("--alpha-codebook 4096: the codebook has only"), std::string::npos) << asked.output;
  EXPECT_EQ(asked.output.find("--codebook 2048"), std::string::npos) << asked.output;
  // `run` and `demo` compress with the same flags and say the same.
  const test::Outcome run =
      RunVoltree("run ws --alpha-codebook 4096 --levels 3 --orbit 1 --orbit-size 32 --force --quiet", dir);
  EXPECT_EQ(run.status, 0) << run.output;
  EXPECT_NE(run.output.find("--alpha-codebook 4096: the codebook has only"), std::string::npos) << run.output;
  const test::Outcome demo = RunVoltree(
      "demo --tree young-oak --views 4 --held-out 1 --size 32x32 --levels 3 --orbit 0 --no-eval --quiet "
      "--alpha-codebook 4096 -o demo",
      dir);
  EXPECT_EQ(demo.status, 0) << demo.output;
  EXPECT_NE(demo.output.find("--alpha-codebook 4096: the codebook has only"), std::string::npos) << demo.output;
  fs::remove_all(dir);
}

// A flag whose behaviour became the default is refused with what to type instead, and nothing is
// written.
TEST(RetiredFlags, SayWhatToTypeInstead) {
  if (!fs::exists(VOLTREE_BINARY)) GTEST_SKIP() << VOLTREE_BINARY << " is not built (build the voltree target)";
  const fs::path dir = fs::temp_directory_path() / Str("voltree_retired_flags_", ::getpid());
  fs::remove_all(dir);
  MakeTinyDemo(dir / "ws");
  for (const std::string flag : {"--alpha-weighted", "--zstd"}) {
    const test::Outcome outcome = RunVoltree("compress ws " + flag + " -o out.vtree --quiet", dir);
    EXPECT_EQ(outcome.status, 1) << outcome.output;
    EXPECT_NE(outcome.output.find("voltree: error: " + flag + " is the default now: drop it (--no-"), std::string::npos)
        << outcome.output;
    EXPECT_FALSE(fs::exists(dir / "out.vtree"));
  }
  const test::Outcome unknown = RunVoltree("compress ws --no-such-flag --quiet", dir);  // CLI11's own message
  EXPECT_NE(unknown.output.find("--no-such-flag"), std::string::npos) << unknown.output;
  EXPECT_EQ(unknown.output.find("the default now"), std::string::npos) << unknown.output;
  fs::remove_all(dir);
}

}  // namespace
}  // namespace voltree
