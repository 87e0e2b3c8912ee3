// `voltree lod-bench` end to end on a tiny OBJ tree at tiny sizes: the table has every method at
// every size, the methods equal the reference at full size, and bad flags are named.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <set>
#include <string>

#include "core/error.h"
#include "core/files.h"
#include "core/vtree.h"
#include "pipeline/voltree_binary.h"
#include "render/test_assets.h"

namespace voltree {
namespace {
namespace fs = std::filesystem;

// A trunk (two triangles, opaque) and 60 leaf cards of the material "leaves", Z up.
void WriteTinyTree(const fs::path& folder) {
  std::string obj =
      "mtllib tiny.mtl\nv -0.05 0 0\nv 0.05 0 0\nv 0.05 0 1\nv -0.05 0 1\nusemtl bark\nf 1 2 3\nf 1 3 4\n";
  std::string faces = "usemtl leaves\n";
  uint64_t state = 3;
  const auto next = [&state] {
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    return static_cast<double>(state >> 40) / static_cast<double>(1ull << 24);
  };
  for (int i = 0; i < 60; ++i) {
    const double x = next() - 0.5, y = next() - 0.5, z = 0.6 + 0.6 * next(), side = 0.08;
    obj += Str("v ", x, " ", y, " ", z, "\nv ", x + side, " ", y, " ", z, "\nv ", x + side, " ", y + 0.3 * side, " ",
               z + side, "\nv ", x, " ", y + 0.3 * side, " ", z + side, "\n");
    const int base = 5 + 4 * i;
    faces += Str("f ", base, " ", base + 1, " ", base + 2, "\nf ", base, " ", base + 2, " ", base + 3, "\n");
  }
  WriteFileAtomic(folder / "tiny.obj", obj + faces);
  WriteFileAtomic(folder / "tiny.mtl", "newmtl bark\nKd 0.4 0.3 0.2\nnewmtl leaves\nKd 0.2 0.6 0.2\n");
}

class LodBenchCli : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / Str("voltree_lod_bench_", ::getpid());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    WriteTinyTree(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  test::Outcome Run(const std::string& arguments) {
    return test::VoltreeCaptured(
        "lod-bench tiny.obj --mesh-up z --size 48 --held-out 2 --top-views 1 --quiet " + arguments, dir_.string());
  }
  fs::path dir_;
};

TEST_F(LodBenchCli, TheTableHasEveryMethodAtEverySizeAndFullSizeMatchesTheReference) {
  const test::Outcome outcome = Run("--sizes 48,24,12 -o out");
  ASSERT_EQ(outcome.status, 0) << outcome.output;
  const std::string table = ReadFile(dir_ / "out" / "table.md");
  const nlohmann::json json = nlohmann::json::parse(ReadFile(dir_ / "out" / "lod_bench.json"));
  EXPECT_EQ(json["leaves"], 60);
  std::set<std::pair<std::string, int>> seen;
  for (const auto& row : json["rows"]) {
    seen.emplace(row["method"], row["size"]);
    const std::string line = Str("| ", row["method"].get<std::string>(), " | ", row["size"].get<int>(), " |");
    EXPECT_NE(table.find(line), std::string::npos) << line;
    const bool primitives = row["method"] == "points" || row["method"] == "ellipsoids";
    if (primitives) {  // points and lines, or ellipsoids and lines: something drawn, compared
      EXPECT_GT(row["primitives"].get<int>() + row["triangles"].get<int>(), 0) << row;
      EXPECT_GT(row["recall"].get<double>(), 0.0) << row;
    } else if (row["size"] == 48) {  // lambda 1: every pruning method draws the full mesh
      EXPECT_EQ(row["precision"], 1.0) << row;
      EXPECT_EQ(row["recall"], 1.0) << row;
      EXPECT_EQ(row["leaves"], 60) << row;
    } else if (row["method"] != "full") {
      EXPECT_LT(row["lambda"].get<double>(), 1.0) << row;
    }
  }
  for (const char* method : {"full", "pruned", "cook", "neubert", "neubert-priority", "neubert-matched",
                             "neubert-colour", "vmi", "points", "ellipsoids"})
    for (int size : {48, 24, 12}) EXPECT_TRUE(seen.count({method, size})) << method << " " << size;
  EXPECT_EQ(seen.size(), 30u);

  // The same inputs and seeds: the same numbers (draw times and fragment counts aside).
  ASSERT_EQ(Run("--sizes 48,24,12 -o again").status, 0);
  nlohmann::json again = nlohmann::json::parse(ReadFile(dir_ / "again" / "lod_bench.json"));
  nlohmann::json first = json;
  for (nlohmann::json* j : {&first, &again}) {
    (*j).erase("preprocess_seconds");
    for (const char* seconds :
         {"vmi_seconds", "priority_seconds", "level_selection_seconds", "skeleton_seconds", "points_seconds",
          "ellipsoid_seconds", "line_merge_seconds", "ellipsoid_calibration_seconds"})
      (*j).erase(seconds);
    for (auto& row : (*j)["rows"]) {  // measured costs, not promised to repeat on every driver
      row.erase("draw_ms");
      row.erase("fragments");
    }
  }
  EXPECT_EQ(first, again);

  // An existing folder is not overwritten without --force.
  const test::Outcome refused = Run("--sizes 48 -o out");
  EXPECT_NE(refused.status, 0);
  EXPECT_NE(refused.output.find("--force"), std::string::npos) << refused.output;
}

// The asset row: a hand-made asset (white cells over the tree's place) drawn at every size.
TEST_F(LodBenchCli, AnAssetGetsARowAtEverySize) {
  WriteAsset(dir_ / "white.vtree", test::WhiteAsset());
  const test::Outcome outcome = Run("--sizes 48,24 --asset white.vtree -o out");
  ASSERT_EQ(outcome.status, 0) << outcome.output;
  const nlohmann::json json = nlohmann::json::parse(ReadFile(dir_ / "out" / "lod_bench.json"));
  std::set<int> sizes;
  for (const auto& row : json["rows"]) {
    if (row["method"] != "asset") continue;
    sizes.insert(row["size"].get<int>());
    EXPECT_GT(row["triangles"].get<int>(), 0) << row;
    EXPECT_GT(row["texture_bytes"].get<int>(), 0) << row;
    EXPECT_GE(row["precision"].get<double>(), 0.0) << row;
    EXPECT_LE(row["recall"].get<double>(), 1.0) << row;
  }
  EXPECT_EQ(sizes, (std::set<int>{48, 24}));
  const test::Outcome missing = Run("--sizes 48 --asset nowhere.vtree -o other");
  EXPECT_NE(missing.status, 0);
  EXPECT_NE(missing.output.find("--asset"), std::string::npos) << missing.output;
}

// A mesh without a leaf material: the pruning methods are not measured, and the table says why;
// the primitive methods draw the bark's lines, or say that there is too little bark for them.
TEST_F(LodBenchCli, AMeshWithoutLeavesGetsTheFullRowsAndANote) {
  WriteFileAtomic(dir_ / "trunk.obj", "v -0.05 0 0\nv 0.05 0 0\nv 0.05 0 1\nv -0.05 0 1\nf 1 2 3\nf 1 3 4\n");
  const test::Outcome outcome = test::VoltreeCaptured(
      "lod-bench trunk.obj --mesh-up z --size 32 --sizes 32,16 --held-out 2 --top-views 0 --quiet -o out",
      dir_.string());
  ASSERT_EQ(outcome.status, 0) << outcome.output;
  const nlohmann::json json = nlohmann::json::parse(ReadFile(dir_ / "out" / "lod_bench.json"));
  EXPECT_EQ(json["methods"], nlohmann::json::array({"full"}));
  EXPECT_EQ(json["rows"].size(), 2u);
  const std::string table = ReadFile(dir_ / "out" / "table.md");
  EXPECT_NE(table.find("need leaves"), std::string::npos);
  EXPECT_NE(table.find("points and ellipsoids were not measured"), std::string::npos) << table;
}

TEST_F(LodBenchCli, BadFlagsAreNamed) {
  const test::Outcome too_big = Run("--sizes 48,96 -o out");
  EXPECT_NE(too_big.status, 0);
  EXPECT_NE(too_big.output.find("--sizes"), std::string::npos) << too_big.output;
  EXPECT_NE(too_big.output.find("96"), std::string::npos) << too_big.output;
  for (const char* lambda : {"0", "1.5", "-0.1"}) {
    const test::Outcome bad = Run(Str("--sizes 48 --min-lambda ", lambda, " -o out"));
    EXPECT_NE(bad.status, 0) << lambda;
    EXPECT_NE(bad.output.find("--min-lambda"), std::string::npos) << bad.output;
  }
  EXPECT_FALSE(fs::exists(dir_ / "out"));
}

}  // namespace
}  // namespace voltree
