// The mattes checked against each other through the cameras: a visual hull carved from all of
// them, each voxel allowed to be outvoted by a few photos, projected back into every photo.
//   recall    of a photo: its tree pixels that the hull's projection covers. Low when the matte
//             holds something no other photo agrees with (the ground or the sky taken as tree).
//   precision of a photo: the hull's voxels it sees that fall on its (dilated) matte. Low when the
//             photo's matte misses what the others agree on (a tree cut out, the wrong photo's
//             matte, a camera that is off).
// A consistent set scores near 1 on both for every photo; the guard names the photos below the
// limits.
#pragma once

#include <string>
#include <vector>

#include "core/camera.h"
#include "core/image.h"

namespace voltree {

struct MatteConsistencyOptions {
  int resolution = 128;           // hull voxels along the longest side of the tree's region
  double matte_threshold = 0.25;  // alpha above which a pixel is the tree (what recall counts)
  // A photo carves a voxel only where its alpha is at most this, sure background. A leaf or twig
  // that covers part of a pixel keeps a fraction of alpha once the mixed pixels are solved, less
  // than the tree's threshold once the matte is shrunk to max_side: carved at that threshold,
  // the aspen's thin branches left the hull and one photo's recall fell to 0.897.
  double carve_threshold = 0.1;
  double outvoted_fraction = 0.1;     // a voxel survives this fraction of photos (at least one) saying "empty"
  double min_seen_fraction = 0.5;     // voxels seen by fewer photos are unconstrained and left out
  double outvoted_share_of_seen = 1;  // and at most this share of the photos that see it
  int max_side = 256;                 // mattes are compared at most this large (the hull is coarser)
  // Limits of the guard. Measured with the true mattes and cameras (carved at matte_threshold,
  // before carve_threshold existed): recall 1.0 on every photo,
  // precision >= 0.979 (oak, 24 views at 384²) and >= 0.949 (young oak, 8 views at 128²). With
  // two of the young oak's 8 mattes taken from photos of a pine: those two 0.77 / 0.88 and
  // 0.87 / 0.86, the others >= 0.94 / 0.95. Silhouettes of one round crown seen 90 degrees apart
  // are too alike to tell apart (oak, two mattes swapped: 0.92 / 0.92 at worst).
  double min_recall = 0.9;
  double min_precision = 0.9;
  // The hull in separate parts, the second at least this fraction of the largest: two objects
  // stand in the ring (two trees, a tree and a post), and one asset cannot hold them apart.
  double max_second_part = 0.2;
  // Fewer photos carve a hull too loose to judge a matte by (4 true mattes of the young oak at
  // 32²: precision 0.68-0.87): the guard then skips this check and says so.
  int min_photos = 8;
  void Check() const;  // throws Error naming the field
};

struct PhotoConsistency {
  std::string name;
  double recall = 0, precision = 0;
};

// A connected part of the visual hull.
struct HullPart {
  size_t voxels = 0;
  Eigen::Vector3d center = Eigen::Vector3d::Zero();  // of its voxels, in the views' frame
};

struct MatteConsistency {
  std::vector<PhotoConsistency> photos;  // in the order of the views
  size_t hull_voxels = 0;
  double voxel_size = 0;
  std::vector<HullPart> parts;  // largest first
};

// `mattes[i]` is views[i]'s 1-channel matte (any size; scaled to the camera). Views in a +Z-up
// frame or not: the region is a cube around the point the cameras look at.
MatteConsistency MeasureMatteConsistency(const std::vector<View>& views, const std::vector<Image8>& mattes,
                                         const MatteConsistencyOptions& options);

// Majority voting over the voxels around the tree: a voxel is the tree's when at least half of
// the photos that see it have it on their matte. A photo's minority votes say how often it
// disagrees with the majority: `carves` voxels the majority keeps (its matte misses the tree),
// `keeps` voxels the majority carves (its matte holds background).
struct MinorityVotes {
  size_t carves = 0, keeps = 0, majority_voxels = 0;
};
std::vector<MinorityVotes> CountMinorityVotes(const std::vector<View>& views, const std::vector<Image8>& mattes,
                                              const MatteConsistencyOptions& options);

// The visual hull as one photo sees it: `mask` at its camera's size, 255 where the hull is, 0
// elsewhere; `far_depth` the camera depth (z) behind which no part of the hull lies.
struct HullProjection {
  Image8 mask;
  double far_depth = 0;
};

// The visual hull carved from the `trusted` photos' mattes (at least 3), projected into each of
// `targets`. The hull holds the tree when the trusted mattes and the cameras are right, so the
// projection bounds the tree in any photo.
std::vector<HullProjection> ProjectHull(const std::vector<View>& views, const std::vector<Image8>& mattes,
                                        const std::vector<bool>& trusted, const std::vector<View>& targets,
                                        const MatteConsistencyOptions& options);

// Throws Error naming the photos below the limits (worst first), what their numbers mean and what
// to try; `mattes_folder` is named in the message.
void CheckMatteConsistency(const MatteConsistency& consistency, const MatteConsistencyOptions& options,
                           const std::string& mattes_folder);

}  // namespace voltree
