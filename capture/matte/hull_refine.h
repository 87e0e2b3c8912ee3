// Mattes from the whole capture: once the cameras are known, the photos whose automatic matte
// disagrees with the others are matted again inside the visual hull of the photos that agree.
//   0. Background told by parallax (backdrop.h: sky and ground a neighbouring photo shows again)
//      is taken out of every matte, and stays background in every re-matting.
//   1. Trust: majority voting over voxels; a photo that often disagrees with the majority (misses
//      what most see as tree, or holds what most see as background) is not trusted. When fewer
//      than a quarter are trusted, the majority hull of all photos bounds the tree instead.
//   2. The hull of the trusted photos alone, projected into each untrusted photo, bounds the
//      tree there: outside it (grown by a band) is background whatever its colour (skyline,
//      bushes, other trees), well inside it the old matte's confident tree stays tree, the rest
//      is unknown and solved from the photo's colours (alphamat::infoFlow by default). An old
//      matte with no tree to seed it (the skyline taken for the tree, the tree against the ground
//      missed) is seeded by GrabCut inside the hull against the photo's background outside it,
//      and so is what the old matte left out of a narrow part of the hull (a trunk cut off
//      against the ground).
//      The sky the photo's own colour model explains stays background (parallax cannot tell
//      it behind the crown: the eye-level ring's neighbours do not see that sky). Near the hull,
//      what two neighbours show at one depth behind it is then taken out (backdrop.h). Parallax
//      claims nothing along the centre lines of the hull's narrow parts: a trunk stands there.
//   3. A matte that misses a narrow part of the majority hull of all (a trunk, a bough) is mended
//      there. Then, up to `guard_passes` times, the photos the guard (matte_consistency.h) would
//      name are matted again the same way inside the hull of those it passes.
//   4. The narrow parts are mended once more.
//   5. The ground behind each photo's tree is found from its neighbours (clean_plate.h), and a
//      trunk whose foot every hull lost is carried down to it (trunk_foot.h).
//   6. Every photo is matted once more where its background is known (mixed_pixels.h), the
//      ground behind the crown's gaps included.
// Photos with sky behind the crown and those with ground behind it fail in different ways, so
// one kind usually corrects the other.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "capture/matte/backdrop.h"
#include "capture/matte/clean_plate.h"
#include "capture/matte/trunk_foot.h"
#include "capture/matte/consistency.h"
#include "capture/matte/mixed_pixels.h"
#include "capture/matte/options.h"
#include "core/camera.h"
#include "core/image.h"
#include "core/progress.h"

namespace voltree {

struct HullRematteOptions {
  // The hulls that bound the re-matting are carved wherever a photo's alpha is under the tree's
  // threshold: the mattes are whole until the last pass (the mixed pixels), and the tighter hull
  // bounds them better (carved at 0.1, the grey trunk of the young oak's test came back at 0.56
  // of its pixels instead of 0.80). The guard that checks the final mattes carves at 0.1.
  MatteConsistencyOptions consistency{.carve_threshold = MatteConsistencyOptions{}.matte_threshold};
  // A photo is trusted when it carves at most this fraction of the majority's voxels and keeps at
  // most this many times the median photo's background voxels (matte_consistency.h).
  double max_carve_fraction = 0.15;
  double max_keep_ratio = 3.0;
  double min_trusted_fraction = 0.25;  // fewer trusted photos: the hull of all by majority instead
  double majority_share = 0.45;        // that hull: a voxel at most this share of its photos call empty
  double confident_alpha = 0.95;       // the old matte's tree kept as known foreground
  int guard_passes = 3;                // re-matting of the photos the guard would name, at most
  // Narrow parts of the hull (thinner than a disc of this many hull bands in radius) that the old
  // matte left out are decided by GrabCut: a trunk the old matte cut off against the ground.
  bool seed_narrow_parts = true;
  int narrow_radius_bands = 6;
  // The sky this photo's colour model explains stays background when it is matted again (the
  // first matte's colour alpha said so; the solver, seeded by the hull alone, blurred the crown's
  // gaps against the sky into it); in the last pass too.
  bool keep_clear_sky = true;
  // Every photo whose matte misses most of a narrow part's centre line, which the others hold,
  // is matted again there (narrow_parts.h), before the guard's passes and after them: a
  // trunk cut off in one photo is carved out of the volume in every view.
  bool mend_narrow_parts = true;
  // Then also the narrow parts of the majority's hull, which more photos may miss than the usual
  // hull lets be outvoted (the aspen at 20°: held-out alpha PSNR 21.63 -> 22.91 dB, recall
  // 0.847 -> 0.893, matte MSE 0.0045 -> 0.0036, on the same cameras).
  bool mend_inside_majority_hull = true;
  double max_missed_narrow = 0.2;  // the share of a part's centre line a matte may miss
  // Background told by parallax does not claim a strip along the centre lines of the hull's narrow
  // parts: a trunk there stands in front of whatever the neighbours show behind it, and one of
  // its colour is explained as well as the backdrop itself (the aspen's grey trunk in front of a
  // grey-green bush lost 22 rows in one eye-level photo, and its matte carved them out of every
  // view). The photo's colours decide the strip instead.
  bool parallax_spares_narrow_parts = true;
  // Last, every photo is matted once more where its background is known, so that the pixels a
  // leaf covers in part are solved instead of whole (mixed_pixels.h).
  bool matte_mixed_pixels = true;
  MixedPixelOptions mixed_pixels;
  // There, the ground behind each pixel as the neighbouring photos show it (clean_plate.h) tells
  // the crown's gaps in front of the ground, which the first mattes filled (the aspen at 20°:
  // matte MSE 0.0055 -> 0.0038, held-out alpha PSNR 21.98 -> 22.67 dB on the same cameras).
  bool use_clean_plate = true;
  CleanPlateOptions clean_plate;
  // Before that pass, a trunk whose foot every hull lost is carried down to the ground in the
  // photos where it stands in front of it (trunk_foot.h; needs the plate).
  bool carry_trunk_to_ground = true;
  TrunkFootOptions trunk_foot;
  MatteOptions matte;  // how the unknown is solved
  // Background told by parallax (backdrop.h) is taken out of every matte first, and stays
  // background when a photo is matted again.
  bool use_backdrop = true;
  BackdropOptions backdrop;
  void Check() const;  // throws Error naming the field
};

struct HullRematteResult {
  std::vector<std::string> trusted, rematted;
  std::vector<std::string> mended;         // photos whose matte missed a narrow part the others hold
  std::vector<std::string> trunk_carried;  // photos whose matte had the trunk's foot carried to the ground
  std::vector<std::string> changed;        // every photo whose matte changed (re-matted or backdrop taken out)
  // Too few were trusted: the majority hull of all bounded the tree, in every pass after the first
  // too.
  bool majority_hull = false;
  std::vector<std::string> votes;  // per photo: its minority votes, the limits, and its verdict
};

// `photos[i]` (RGB) and `mattes[i]` (1 channel, replaced for re-matted photos) belong to views[i].
HullRematteResult RematteFromHull(const std::vector<View>& views, const std::vector<Image8>& photos,
                                  std::vector<Image8>& mattes, const HullRematteOptions& options);

// The workspace form: DIR/sparse/, DIR/images/, DIR/mattes/ in; the re-matted photos' mattes and
// foregrounds replaced (each file written aside and renamed).
HullRematteResult RematteWorkspaceFromHull(const std::filesystem::path& dir, const HullRematteOptions& options,
                                           Progress& progress);

}  // namespace voltree
