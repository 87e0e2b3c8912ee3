#include "capture/colmap_database.h"

#include <sqlite3.h>

#include <algorithm>
#include <map>
#include <memory>

#include "core/error.h"

namespace voltree {
namespace fs = std::filesystem;

namespace {

// COLMAP packs an unordered image pair into one integer (src/base/database.cc).
constexpr int64_t kMaxImageId = 2147483647;

struct SqliteCloser {
  void operator()(sqlite3* db) const { sqlite3_close(db); }
};
struct StatementFinalizer {
  void operator()(sqlite3_stmt* statement) const { sqlite3_finalize(statement); }
};
using Database = std::unique_ptr<sqlite3, SqliteCloser>;
using Statement = std::unique_ptr<sqlite3_stmt, StatementFinalizer>;

Statement Prepare(sqlite3* db, const fs::path& path, const char* sql) {
  sqlite3_stmt* statement = nullptr;
  if (sqlite3_prepare_v2(db, sql, -1, &statement, nullptr) != SQLITE_OK)
    Fail(path.string(), ": not a COLMAP database (", sqlite3_errmsg(db), " in \"", sql, "\")");
  return Statement(statement);
}

// Calls `row` for every row of `sql`; throws when stepping fails (a damaged file).
template <typename Row>
void ForEachRow(sqlite3* db, const fs::path& path, const char* sql, Row row) {
  Statement statement = Prepare(db, path, sql);
  int status;
  while ((status = sqlite3_step(statement.get())) == SQLITE_ROW) row(statement.get());
  if (status != SQLITE_DONE) Fail(path.string(), ": cannot read COLMAP's database: ", sqlite3_errmsg(db));
}

std::string Text(sqlite3_stmt* statement, int column) {
  const unsigned char* text = sqlite3_column_text(statement, column);
  return text ? reinterpret_cast<const char*>(text) : "";
}

}  // namespace

std::vector<PhotoMatches> ReadPhotoMatches(const fs::path& database) {
  if (!fs::is_regular_file(database)) Fail(database.string(), ": no such file (expected COLMAP's feature database)");
  sqlite3* raw = nullptr;
  const int opened = sqlite3_open_v2(database.c_str(), &raw, SQLITE_OPEN_READONLY, nullptr);
  Database db(raw);
  if (opened != SQLITE_OK)
    Fail(database.string(), ": cannot open COLMAP's database: ", raw ? sqlite3_errmsg(raw) : "out of memory");

  std::map<int64_t, PhotoMatches> by_id;
  ForEachRow(db.get(), database, "SELECT image_id, name FROM images",
             [&](sqlite3_stmt* row) { by_id[sqlite3_column_int64(row, 0)].name = Text(row, 1); });
  ForEachRow(db.get(), database, "SELECT image_id, rows FROM keypoints", [&](sqlite3_stmt* row) {
    const auto photo = by_id.find(sqlite3_column_int64(row, 0));
    if (photo != by_id.end()) photo->second.features = sqlite3_column_int(row, 1);
  });
  ForEachRow(db.get(), database, "SELECT pair_id, rows FROM two_view_geometries WHERE rows > 0",
             [&](sqlite3_stmt* row) {
               const int64_t pair = sqlite3_column_int64(row, 0);
               const int matches = sqlite3_column_int(row, 1);
               const int64_t second = pair % kMaxImageId, first = (pair - second) / kMaxImageId;
               const auto a = by_id.find(first), b = by_id.find(second);
               if (a == by_id.end() || b == by_id.end()) return;
               for (auto [one, other] : {std::pair{a, b}, std::pair{b, a}}) {
                 PhotoMatches& photo = one->second;
                 ++photo.matched_photos;
                 if (matches > photo.best_matches) {
                   photo.best_matches = matches;
                   photo.best_partner = other->second.name;
                 }
               }
             });

  std::vector<PhotoMatches> photos;
  for (auto& [id, photo] : by_id) photos.push_back(std::move(photo));
  std::sort(photos.begin(), photos.end(), [](const auto& a, const auto& b) { return a.name < b.name; });
  return photos;
}

std::string WhyNotRegistered(const PhotoMatches& photo, int min_pose_inliers) {
  // Below ~100 features SIFT found almost no texture: a blank, blurred or tiny photo.
  if (photo.features < 100)
    return Str(photo.features, " features: too little texture (a blank, blurred or dark photo?)");
  if (photo.matched_photos == 0)
    return Str(photo.features, " features, none matched in any other photo: it overlaps no other photo");
  if (photo.best_matches < min_pose_inliers)
    return Str(photo.features, " features, at most ", photo.best_matches, " matched with one photo (",
               photo.best_partner, "), fewer than the ", min_pose_inliers,
               " needed to place it: take photos closer together around it");
  return Str(photo.features, " features, ", photo.best_matches, " matched with ", photo.best_partner, " (",
             photo.matched_photos, " photos in all), but the mapper could not place it among the others: ",
             "too few of its matches were triangulated (photos farther around the tree, or at a much "
             "higher or lower angle, than its neighbours)");
}

}  // namespace voltree
