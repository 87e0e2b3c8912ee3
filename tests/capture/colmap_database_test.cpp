// Reading COLMAP's feature database for the reasons a photo did not register: a database with
// COLMAP's tables (the columns voltree reads) written by hand, so every count is known.
#include <gtest/gtest.h>
#include <sqlite3.h>
#include <unistd.h>

#include <filesystem>
#include <string>

#include "capture/colmap_database.h"
#include "core/error.h"
#include "core/files.h"

namespace voltree {
namespace {
namespace fs = std::filesystem;

fs::path TempPath(const std::string& name) {
  return fs::path(::testing::TempDir()) / ("voltree_colmap_db_" + std::to_string(::getpid()) + "_" + name);
}

void Execute(sqlite3* db, const std::string& sql) {
  char* message = nullptr;
  ASSERT_EQ(sqlite3_exec(db, sql.c_str(), nullptr, nullptr, &message), SQLITE_OK) << message;
}

int64_t PairId(int64_t a, int64_t b) { return a < b ? a * 2147483647 + b : b * 2147483647 + a; }

// Four photos: a and b match well, c matches b a little, d is blank.
fs::path WriteDatabase() {
  const fs::path path = TempPath("four.db");
  fs::remove(path);
  sqlite3* db = nullptr;
  EXPECT_EQ(sqlite3_open(path.c_str(), &db), SQLITE_OK);
  Execute(db, "CREATE TABLE images (image_id INTEGER PRIMARY KEY, name TEXT, camera_id INTEGER)");
  Execute(db, "CREATE TABLE keypoints (image_id INTEGER PRIMARY KEY, rows INTEGER, cols INTEGER, data BLOB)");
  Execute(db, "CREATE TABLE two_view_geometries (pair_id INTEGER PRIMARY KEY, rows INTEGER, cols INTEGER, data BLOB)");
  Execute(db, "INSERT INTO images VALUES (1, 'a.png', 1), (2, 'b.png', 1), (3, 'c.png', 1), (4, 'd.png', 1)");
  Execute(db, "INSERT INTO keypoints VALUES (1, 900, 6, NULL), (2, 800, 6, NULL), (3, 700, 6, NULL), (4, 0, 6, NULL)");
  Execute(db, "INSERT INTO two_view_geometries VALUES (" + std::to_string(PairId(1, 2)) + ", 250, 2, NULL), (" +
                  std::to_string(PairId(3, 2)) + ", 9, 2, NULL), (" + std::to_string(PairId(1, 3)) + ", 0, 2, NULL)");
  sqlite3_close(db);
  return path;
}

TEST(ColmapDatabase, CountsFeaturesAndVerifiedMatchesPerPhoto) {
  const std::vector<PhotoMatches> photos = ReadPhotoMatches(WriteDatabase());
  ASSERT_EQ(photos.size(), 4u);
  EXPECT_EQ(photos[0].name, "a.png");
  EXPECT_EQ(photos[0].features, 900);
  EXPECT_EQ(photos[0].matched_photos, 1);  // the pair with c has no verified match
  EXPECT_EQ(photos[0].best_matches, 250);
  EXPECT_EQ(photos[0].best_partner, "b.png");
  EXPECT_EQ(photos[1].matched_photos, 2);
  EXPECT_EQ(photos[1].best_partner, "a.png");
  EXPECT_EQ(photos[2].best_matches, 9);
  EXPECT_EQ(photos[2].best_partner, "b.png");
  EXPECT_EQ(photos[3].features, 0);
  EXPECT_EQ(photos[3].matched_photos, 0);
}

TEST(ColmapDatabase, SaysWhyAPhotoStayedOut) {
  const std::vector<PhotoMatches> photos = ReadPhotoMatches(WriteDatabase());
  EXPECT_EQ(WhyNotRegistered(photos[3], 15).find("0 features: too little texture"), 0u);
  EXPECT_NE(WhyNotRegistered(photos[2], 15).find("at most 9 matched with one photo (b.png), fewer than the 15"),
            std::string::npos);
  EXPECT_NE(WhyNotRegistered(photos[0], 15).find("the mapper could not place it"), std::string::npos);
  PhotoMatches alone{"e.png", 500, 0, 0, ""};
  EXPECT_NE(WhyNotRegistered(alone, 15).find("overlaps no other photo"), std::string::npos);
}

TEST(ColmapDatabase, NamesAFileThatIsNotADatabase) {
  const fs::path text = TempPath("text.db");
  fs::remove(text);
  WriteFileAtomic(text, "images.txt is not a database\n");
  try {
    ReadPhotoMatches(text);
    FAIL() << "a text file was read as a database";
  } catch (const Error& error) {
    EXPECT_NE(std::string(error.what()).find(text.string()), std::string::npos) << error.what();
  }
  try {
    ReadPhotoMatches(TempPath("missing.db"));
    FAIL() << "a missing file was read";
  } catch (const Error& error) {
    EXPECT_NE(std::string(error.what()).find("expected COLMAP's feature database"), std::string::npos) << error.what();
  }
}

}  // namespace
}  // namespace voltree
