// What COLMAP's feature database (DIR/colmap/database.db) says about each photo: how many features
// it found and how many of them it verified against every other photo. Read after mapping to tell
// a user why a photo did not register, in words about the photos rather than COLMAP's log.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace voltree {

struct PhotoMatches {
  std::string name;  // the photo's file name, as COLMAP names it
  int features = 0;
  int matched_photos = 0;    // photos it shares at least one verified match with
  int best_matches = 0;      // most verified matches with any one photo
  std::string best_partner;  // that photo
};

// One entry per photo in the database, sorted by name. Throws Error naming the file when it cannot
// be opened or does not hold COLMAP's tables.
std::vector<PhotoMatches> ReadPhotoMatches(const std::filesystem::path& database);

// Why a photo with these matches may have stayed out of the model, in a few words with a hint:
// too few features, no overlap with any other photo, too few matches, or placed by nobody.
// `min_pose_inliers` is the mapper's threshold.
std::string WhyNotRegistered(const PhotoMatches& photo, int min_pose_inliers);

}  // namespace voltree
