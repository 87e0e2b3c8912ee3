#include "capture/matte/hull_refine.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <optional>
#include <opencv2/imgproc.hpp>

#include "capture/colmap_binary.h"
#include "capture/matte/clean_plate.h"
#include "capture/matte/cv.h"
#include "capture/matte/foreground.h"
#include "capture/matte/grabcut.h"
#include "capture/matte/mixed_pixels.h"
#include "capture/matte/narrow_parts.h"
#include "capture/matte/refine.h"
#include "capture/matte/sky_estimate.h"
#include "capture/matte/trunk_foot.h"
#include "capture/matte/workspace.h"
#include "core/error.h"
#include "core/fixed.h"

namespace voltree {
namespace fs = std::filesystem;

void HullRematteOptions::Check() const {
  consistency.Check();
  matte.Check();
  if (!(max_carve_fraction > 0 && max_carve_fraction < 1))
    FailOption("HullRematteOptions.max_carve_fraction", "must be in (0, 1), got ", max_carve_fraction);
  if (!(max_keep_ratio >= 1))
    FailOption("HullRematteOptions.max_keep_ratio", "must be at least 1, got ", max_keep_ratio);
  if (!(min_trusted_fraction > 0 && min_trusted_fraction <= 1))
    Fail("min trusted fraction must be in (0, 1], got ", min_trusted_fraction);
  if (guard_passes < 0 || guard_passes > 10) Fail("guard passes must be 0..10, got ", guard_passes);
  if (!(confident_alpha > 0 && confident_alpha <= 1)) Fail("confident alpha must be in (0, 1], got ", confident_alpha);
  if (!(majority_share > 0 && majority_share < 1)) Fail("majority share must be in (0, 1), got ", majority_share);
  if (!(max_missed_narrow > 0 && max_missed_narrow < 1))
    FailOption("HullRematteOptions.max_missed_narrow", "must be in (0, 1), got ", max_missed_narrow);
  if (narrow_radius_bands < 1 || narrow_radius_bands > 64)
    FailOption("HullRematteOptions.narrow_radius_bands", "must be in [1, 64], got ", narrow_radius_bands);
  if (use_backdrop) backdrop.Check();
  if (matte_mixed_pixels) mixed_pixels.Check();
  if (use_clean_plate) clean_plate.Check();
  if (use_clean_plate && carry_trunk_to_ground) trunk_foot.Check();
}

namespace {

// One photo's minority votes against the limits of trust, and what became of its matte.
std::string DescribeVotes(const std::string& name, const MinorityVotes& vote, double median_keeps,
                          const HullRematteResult& result, const HullRematteOptions& options) {
  const auto percent = [](double share) { return Str(FixedDecimals(100 * share, 1), " %"); };
  const auto holds = [&](const std::vector<std::string>& names) {
    return std::find(names.begin(), names.end(), name) != names.end();
  };
  return Str(name, ": carves ", percent(double(vote.carves) / std::max<double>(vote.majority_voxels, 1)),
             " of the voxels the majority holds (at most ", percent(options.max_carve_fraction), "), keeps ",
             vote.keeps, " the majority carves (", FixedDecimals(double(vote.keeps) / std::max(median_keeps, 1.0), 1),
             " times the median photo, at most ", FixedDecimals(options.max_keep_ratio, 1),
             "): ", holds(result.trusted) ? "trusted" : "not trusted", holds(result.rematted) ? ", matted again" : "",
             holds(result.mended) ? ", a narrow part mended" : "");
}

// How far beyond the hull's projection a photo is still matted (the hull is coarse).
int HullBand(int width, int height) { return std::max(2, std::min(width, height) / 128); }
int HullBand(const Image8& photo) { return HullBand(photo.width, photo.height); }

// Appends the names `list` does not hold yet.
void AppendNew(const std::vector<std::string>& names, std::vector<std::string>& list) {
  for (const std::string& name : names)
    if (std::find(list.begin(), list.end(), name) == list.end()) list.push_back(name);
}

// Where parallax may not claim background in a photo whose hull projection is `hull` (empty when
// it may everywhere): a strip half a band wide each side of the narrow parts' centre lines.
cv::Mat SparedFromParallax(const Image8& hull, const HullRematteOptions& options) {
  if (!options.parallax_spares_narrow_parts) return {};
  const int band = HullBand(hull.width, hull.height);
  cv::Mat strip;
  cv::dilate(matte::NarrowCentreLines(matte::View(hull), options.narrow_radius_bands * band, band), strip,
             matte::Disc(band / 2));
  return strip;
}

// `known` (CV_8U, nonzero: background) without `spared`; either may be empty.
cv::Mat WithoutSpared(const cv::Mat& known, const cv::Mat& spared) {
  if (known.empty() || spared.empty()) return known;
  return (known != 0) & (spared == 0);
}

// "a, b, c", for the progress line.
std::string NameList(const std::vector<std::string>& names) {
  std::string list;
  for (const std::string& name : names) list += (list.empty() ? "" : ", ") + name;
  return list;
}

// GrabCut's labels for a photo matted inside the hull's projection: probably tree inside it,
// certain background outside it grown by a band and where the backdrop explains the pixel,
// probably background in between.
cv::Mat HullGrabCutLabels(const cv::Mat& inside, const cv::Mat& grown, const Image8* backdrop) {
  cv::Mat labels(inside.size(), CV_8UC1, cv::Scalar(cv::GC_PR_BGD));
  labels.setTo(cv::GC_PR_FGD, inside != 0);
  labels.setTo(cv::GC_BGD, grown == 0);
  if (backdrop != nullptr) labels.setTo(cv::GC_BGD, matte::View(*backdrop) != 0);
  return labels;
}

// Where the hull is narrow (the trunk, a bough: the silhouettes of a column agree closely) it
// bounds the tree tightly, so what the old matte left out there it missed; it is not a gap of the
// crown. The eye-level photos' first mattes cut the aspen's thin grey trunk off against the grey
// soil, and the solver, seeded only by the crown far above, kept it cut off. GrabCut, told the
// old matte's confident tree and the photo's background outside the hull, decides those parts.
// CV_8U, 255 where it finds the tree there.
cv::Mat NarrowPartsTheOldMatteMissed(const cv::Mat& rgb, const cv::Mat& old_alpha, const cv::Mat& inside,
                                     const cv::Mat& grown, const cv::Mat& trimap, const Image8* backdrop,
                                     const HullRematteOptions& options) {
  const cv::Mat missed =
      matte::NarrowParts(inside, options.narrow_radius_bands * HullBand(rgb.cols, rgb.rows)) & (old_alpha < 128);
  if (cv::countNonZero(missed) == 0) return missed;
  cv::Mat labels = HullGrabCutLabels(inside, grown, backdrop);
  labels.setTo(cv::GC_FGD, (trimap == 255) & (labels != cv::GC_BGD));
  return matte::GrabCutForeground(rgb, labels, 5, options.matte.grabcut_max_side) & missed;
}

// What each photo is known to show behind the tree, found once: the background told by parallax
// (backdrop.h; empty when not used) and the sky the photo's own colour model explains (empty when
// not kept). Parallax cannot tell that sky behind the crown: with a narrow lens the neighbours of
// the eye-level ring do not see it at all.
struct KnownBackground {
  std::vector<Image8> parallax, clear_sky;
  std::vector<matte::SkyEstimate> skies;  // estimated once; empty when no pass needs them
  const Image8* Parallax(size_t i) const { return parallax.empty() ? nullptr : &parallax[i]; }
  const Image8* ClearSky(size_t i) const { return clear_sky.empty() ? nullptr : &clear_sky[i]; }
  // Either, CV_8U (nonzero: background), the parallax without `spared` (may be empty); empty when
  // neither is known.
  cv::Mat Either(size_t i, const cv::Mat& spared) const {
    cv::Mat either;
    if (Parallax(i) != nullptr) either = WithoutSpared(matte::View(*Parallax(i)), spared);
    if (ClearSky(i) != nullptr)
      either = either.empty() ? matte::View(*ClearSky(i)) != 0 : either | (matte::View(*ClearSky(i)) != 0);
    return either;
  }
};

// Re-mattes one photo inside the hull's projection `hull` (255 inside).
Image8 MatteInsideHull(const Image8& photo, const Image8& old_matte, const Image8& hull, const Image8* backdrop,
                       const Image8* clear_sky, const HullRematteOptions& options) {
  const cv::Mat rgb = matte::View(photo);
  const cv::Mat old_alpha = matte::View(old_matte);
  const cv::Mat inside = matte::View(hull);
  const int band = HullBand(photo);
  cv::Mat grown, shrunk;
  cv::dilate(inside, grown, matte::Disc(band));
  cv::erode(inside, shrunk, matte::Disc(2 * band));
  cv::Mat trimap(photo.height, photo.width, CV_8UC1, cv::Scalar(128));
  trimap.setTo(0, grown == 0);
  trimap.setTo(255, (shrunk != 0) & (old_alpha >= options.confident_alpha * 255));
  cv::Mat estimate;
  old_alpha.convertTo(estimate, CV_32F, 1.0 / 255.0);
  // An old matte that missed the tree leaves (almost) no seed (an eye-level photo whose first
  // matte took the skyline for the tree and the tree for ground). GrabCut then finds the tree by
  // its colours inside the hull's projection, against this photo's own background outside it,
  // and its edges become the unknown band.
  const bool seedless = cv::countNonZero(trimap == 255) < 0.1 * cv::countNonZero(inside);
  if (seedless) {
    const cv::Mat labels = HullGrabCutLabels(inside, grown, backdrop);
    const cv::Mat tree = matte::GrabCutForeground(rgb, labels, 5, options.matte.grabcut_max_side) & (grown != 0);
    const int radius = options.matte.BandRadius(photo.width, photo.height);
    cv::Mat sure, near;
    cv::erode(tree, sure, matte::Disc(radius));
    cv::dilate(tree, near, matte::Disc(radius));
    trimap.setTo(0, near == 0);
    trimap.setTo(255, sure != 0);
    tree.convertTo(estimate, CV_32F, 1.0 / 255.0);
  }
  if (!seedless && options.seed_narrow_parts) {
    const cv::Mat tree = NarrowPartsTheOldMatteMissed(rgb, old_alpha, inside, grown, trimap, backdrop, options);
    trimap.setTo(255, tree);
    estimate.setTo(1.0f, tree);
  }
  if (backdrop != nullptr) {
    const cv::Mat background = matte::View(*backdrop) != 0;
    trimap.setTo(0, background);
    estimate.setTo(0.0f, background);
  }
  if (clear_sky != nullptr) {
    const cv::Mat sky = matte::View(*clear_sky) != 0;
    trimap.setTo(0, sky);
    estimate.setTo(0.0f, sky);
  }
  estimate.setTo(0.0f, grown == 0);
  const cv::Mat solve = trimap == 128;
  const cv::Mat alpha = matte::RefineAlpha(rgb, estimate, trimap, solve, options.matte);
  return matte::ToImage8(matte::AlphaTo8(alpha));
}

}  // namespace

namespace {

// What lies behind the hull near its projection, where the photo is matted again; the pixels the
// far and ground hypotheses explained (`backdrop`) are not asked again, nor those `spared` (may be
// empty) from parallax.
Image8 BehindHullNearIt(const std::vector<View>& views, const std::vector<Image8>& photos,
                        const std::vector<HullProjection>& hulls, size_t target, const Image8& backdrop,
                        const cv::Mat& spared, const BackdropOptions& options) {
  cv::Mat region;
  cv::dilate(matte::View(hulls[target].mask), region, matte::Disc(HullBand(photos[target])));
  region.setTo(0, matte::View(backdrop) != 0);
  if (!spared.empty()) region.setTo(0, spared);
  return ExplainedBehindHull(views, photos, hulls, target, matte::ToImage8(region), options);
}

// Carving by majority: a voxel stays when fewer than `majority_share` of the photos that see it
// call it empty.
MatteConsistencyOptions MajorityCarving(const HullRematteOptions& options) {
  MatteConsistencyOptions carving = options.consistency;
  carving.outvoted_fraction = 0.49;
  carving.outvoted_share_of_seen = options.majority_share;
  return carving;
}

// Mends every matte that misses a narrow part of the hull of all photos (narrow_parts.h): first
// the usual hull, which lets a few photos be outvoted and bounds a trunk tightly; then, where
// more photos missed it than that hull lets be outvoted (at 20° the aspen's grey trunk stands
// against grey soil in all twelve eye-level photos), the majority's hull, which still holds it.
// The majority's alone is looser and mends less well (the young oak's grey trunk: recall 0.811
// against 0.918). Returns the mended photos' names.
std::vector<std::string> MendNarrowParts(const std::vector<View>& views, const std::vector<Image8>& photos,
                                         std::vector<Image8>& mattes, const KnownBackground& known,
                                         const HullRematteOptions& options) {
  std::vector<MatteConsistencyOptions> carvings{options.consistency};
  if (options.mend_inside_majority_hull) carvings.push_back(MajorityCarving(options));
  std::vector<uint8_t> mended(views.size(), 0);
  for (const MatteConsistencyOptions& carving : carvings) {
    const std::vector<HullProjection> hulls =
        ProjectHull(views, mattes, std::vector<bool>(views.size(), true), views, carving);
    tbb::parallel_for(size_t(0), views.size(), [&](size_t i) {
      const int band = HullBand(photos[i]);
      const matte::NarrowPartMend mend{options.narrow_radius_bands * band, band, options.max_missed_narrow};
      cv::Mat alpha = matte::View(mattes[i]);  // shares the matte's pixels
      mended[i] |= uint8_t(matte::MendMissedNarrowParts(matte::View(photos[i]), matte::View(hulls[i].mask),
                                                        known.Either(i, SparedFromParallax(hulls[i].mask, options)),
                                                        mend, options.matte, alpha));
    });
  }
  std::vector<std::string> names;
  for (size_t i = 0; i < views.size(); ++i)
    if (mended[i]) names.push_back(views[i].name);
  return names;
}

// Re-mattes the photos not `trusted` inside the hull of the trusted ones; returns their names
// (none when too few are trusted).
std::vector<std::string> RematteUntrusted(const std::vector<View>& views, const std::vector<Image8>& photos,
                                          std::vector<Image8>& mattes, const std::vector<bool>& trusted,
                                          const KnownBackground& known, const HullRematteOptions& options,
                                          bool* majority_hull) {
  std::vector<View> targets;
  std::vector<size_t> target_index;
  for (size_t i = 0; i < views.size(); ++i)
    if (!trusted[i]) {
      targets.push_back(views[i]);
      target_index.push_back(i);
    }
  const size_t trusted_count = views.size() - targets.size();
  if (targets.empty()) return {};
  // Too few trusted photos bound the tree too loosely (five of 24: matte MSE 0.77); then every
  // photo votes, and a voxel stays when fewer than half of those that see it call it empty.
  MatteConsistencyOptions carving = options.consistency;
  std::vector<bool> carvers = trusted;
  if (double(trusted_count) < options.min_trusted_fraction * double(views.size()) || trusted_count < 3) {
    carving = MajorityCarving(options);
    carvers.assign(views.size(), true);
    *majority_hull = true;
  }
  // The sweep behind the hull looks into the neighbours' hulls too: project it into every photo.
  const bool sweep = !known.parallax.empty() && options.backdrop.behind_neighbours > 0;
  const std::vector<HullProjection> hulls = ProjectHull(views, mattes, carvers, sweep ? views : targets, carving);
  std::vector<Image8> rematted(targets.size());
  tbb::parallel_for(size_t(0), targets.size(), [&](size_t t) {
    const size_t i = target_index[t];
    const Image8& hull = hulls[sweep ? i : t].mask;
    const cv::Mat spared = SparedFromParallax(hull, options);
    std::optional<Image8> parallax;
    if (known.Parallax(i) != nullptr)
      parallax = matte::ToImage8(WithoutSpared(matte::View(*known.Parallax(i)), spared));
    rematted[t] =
        MatteInsideHull(photos[i], mattes[i], hull, parallax ? &*parallax : nullptr, known.ClearSky(i), options);
    // Taken out afterwards, not handed to the solver as known background: there the grey of the
    // hazy hills claimed the aspen's thin trunk (held-out recall 0.947 -> 0.837).
    if (sweep)
      matte::View(rematted[t])
          .setTo(0, matte::View(
                        BehindHullNearIt(views, photos, hulls, i, known.parallax[i], spared, options.backdrop)) != 0);
  });
  std::vector<std::string> names;
  for (size_t t = 0; t < targets.size(); ++t) {
    mattes[target_index[t]] = std::move(rematted[t]);
    names.push_back(targets[t].name);
  }
  return names;
}

}  // namespace

HullRematteResult RematteFromHull(const std::vector<View>& views, const std::vector<Image8>& photos,
                                  std::vector<Image8>& mattes, const HullRematteOptions& options) {
  options.Check();
  if (views.size() != photos.size() || views.size() != mattes.size())
    Fail("re-matting needs one photo and one matte per view");
  const std::vector<Image8> before = mattes;
  KnownBackground known;
  if (options.use_backdrop) known.parallax.resize(views.size());
  if (options.keep_clear_sky) known.clear_sky.resize(views.size());
  if (options.keep_clear_sky || options.matte_mixed_pixels) known.skies.resize(views.size());
  tbb::parallel_for(size_t(0), views.size(), [&](size_t i) {
    if (options.use_backdrop) known.parallax[i] = ExplainedByBackdrop(views, photos, before, i, options.backdrop);
    if (!known.skies.empty()) known.skies[i] = matte::EstimatePhotoSky(matte::View(photos[i]), options.matte);
    if (options.keep_clear_sky) known.clear_sky[i] = matte::ToImage8(known.skies[i].ClearSky());
  });
  if (options.use_backdrop)
    for (size_t i = 0; i < views.size(); ++i) matte::View(mattes[i]).setTo(0, matte::View(known.parallax[i]) != 0);
  // Pass 1, trust by majority: few minority votes of either kind. Keeps are relative to the
  // median photo's (every matte keeps some background voxels that happen to project onto the
  // tree). This survives half of the mattes being wrong.
  const std::vector<MinorityVotes> votes = CountMinorityVotes(views, mattes, options.consistency);
  std::vector<size_t> keeps;
  for (const MinorityVotes& vote : votes) keeps.push_back(vote.keeps);
  std::nth_element(keeps.begin(), keeps.begin() + keeps.size() / 2, keeps.end());
  const double median_keeps = double(keeps[keeps.size() / 2]);
  std::vector<bool> trusted(views.size());
  HullRematteResult result;
  for (size_t i = 0; i < views.size(); ++i) {
    const MinorityVotes& vote = votes[i];
    trusted[i] = double(vote.carves) <= options.max_carve_fraction * double(vote.majority_voxels) &&
                 double(vote.keeps) <= options.max_keep_ratio * std::max(median_keeps, 1.0);
    if (trusted[i]) result.trusted.push_back(views[i].name);
  }
  result.rematted = RematteUntrusted(views, photos, mattes, trusted, known, options, &result.majority_hull);
  // A trunk the first pass left out of a few photos is mended before the guard's passes: their
  // hull lets only a few photos be outvoted, so it would carve the trunk, and every photo matted
  // again inside it would lose it too (the aspen at 20°: 9 of 12 eye-level mattes).
  if (options.mend_narrow_parts) result.mended = MendNarrowParts(views, photos, mattes, known, options);
  // Then trust by the guard's own test (matte_consistency.h) on the mended set: the photos it
  // would name are matted again inside the hull of those it passes, a few times (each pass starts
  // from the last mattes; measured on the oak at 512²: MSE mean 0.011 -> 0.006 from one more).
  for (int pass = 0; pass < options.guard_passes; ++pass) {
    const MatteConsistency scores = MeasureMatteConsistency(views, mattes, options.consistency);
    bool all_pass = true;
    for (size_t i = 0; i < views.size(); ++i) {
      trusted[i] = scores.photos[i].recall >= options.consistency.min_recall &&
                   scores.photos[i].precision >= options.consistency.min_precision;
      all_pass = all_pass && trusted[i];
    }
    if (all_pass) break;
    const std::vector<std::string> names =
        RematteUntrusted(views, photos, mattes, trusted, known, options, &result.majority_hull);
    if (names.empty()) break;
    AppendNew(names, result.rematted);
  }
  if (options.mend_narrow_parts) AppendNew(MendNarrowParts(views, photos, mattes, known, options), result.mended);
  // Every photo's plate is found from the mattes as they stand, before any is changed again.
  std::vector<CleanPlate> plates(options.use_clean_plate ? views.size() : 0);
  tbb::parallel_for(size_t(0), plates.size(), [&](size_t i) {
    plates[i] = GroundCleanPlate(views, photos, mattes, i, mattes[i], options.clean_plate);
  });
  if (options.carry_trunk_to_ground && options.use_clean_plate)
    result.trunk_carried =
        CarryTrunkToGround(views, photos, options.matte, options.clean_plate, options.trunk_foot, mattes);
  if (options.matte_mixed_pixels)
    tbb::parallel_for(size_t(0), views.size(), [&](size_t i) {
      mattes[i] = MatteMixedPixels(photos[i], mattes[i], known.skies[i], known.ClearSky(i),
                                   plates.empty() ? nullptr : &plates[i], options.matte, options.mixed_pixels);
    });
  for (size_t i = 0; i < views.size(); ++i)
    if (mattes[i].pixels != before[i].pixels) result.changed.push_back(views[i].name);
  for (size_t i = 0; i < views.size(); ++i)
    result.votes.push_back(DescribeVotes(views[i].name, votes[i], median_keeps, result, options));
  return result;
}

HullRematteResult RematteWorkspaceFromHull(const fs::path& dir, const HullRematteOptions& options, Progress& progress) {
  const std::vector<View> views = ReadColmapModel(dir / "sparse").Views();
  std::vector<Image8> photos, mattes;
  for (const View& view : views) {
    photos.push_back(ReadImage8(dir / "images" / view.name, 3));
    const fs::path matte = dir / "mattes" / (fs::path(view.name).stem().string() + ".png");
    if (!fs::is_regular_file(matte)) Fail(matte.string(), ": missing matte for photo ", view.name);
    mattes.push_back(ReadImage8(matte, 1));
  }
  const HullRematteResult result = RematteFromHull(views, photos, mattes, options);
  for (size_t i = 0; i < views.size(); ++i) {
    if (std::find(result.changed.begin(), result.changed.end(), views[i].name) == result.changed.end()) continue;
    const std::string name = fs::path(views[i].name).stem().string() + ".png";
    WriteImage(dir / "mattes" / name, mattes[i]);
    WriteImage(dir / "foreground" / name, PremultipliedForeground(photos[i], mattes[i]));
  }
  progress.Say(
      "matte",
      Str(result.trusted.size(), " of ", views.size(), " mattes agree through the cameras; ",
          result.rematted.empty() ? std::string("none re-matted")
                                  : Str(result.rematted.size(), " re-matted inside the visual hull ",
                                        result.majority_hull ? "all photos agree on by majority" : "of those"),
          options.use_backdrop ? "; background told by parallax taken out" : "",
          result.mended.empty() ? std::string()
                                : Str("; ", result.mended.size(), " missed a trunk or bough the others hold (",
                                      NameList(result.mended), "), mended"),
          result.trunk_carried.empty() ? std::string()
                                       : Str("; the trunk's foot, lost above the ground, carried down to it in ",
                                             result.trunk_carried.size(), " (", NameList(result.trunk_carried), ")"),
          options.matte_mixed_pixels ? "; pixels a leaf covers in part matted again" : "", "; ", result.changed.size(),
          " mattes changed"));
  return result;
}

}  // namespace voltree
