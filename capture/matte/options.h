// Options of automatic alpha matting: how the trimap is built and how its unknown band is solved.
#pragma once

#include <string>

namespace voltree {

// How the unknown band of the trimap is solved.
//  kGuided:   guided filter of the first alpha, guided by the photo (fastest).
//  kInfoFlow: OpenCV alphamat::infoFlow (Aksoy et al. 2017) on tiles holding the unknown band;
//             the default: the most accurate in every measurement (bench/matte.cpp: studio oak
//             256 px MSE 11.3 vs 13.0 guided, at 1.6 vs 0.9 s per image on the loaded 2-core box).
//  kNone:     the colour-model alpha as is (a baseline for benchmarks).
enum class RefineMethod { kGuided, kInfoFlow, kNone };

// "guided" | "infoflow" | "none"; throws Error naming the accepted values.
RefineMethod ParseRefineMethod(const std::string& name);
std::string RefineMethodName(RefineMethod method);

struct MatteOptions {
  RefineMethod refine = RefineMethod::kInfoFlow;
  // Row of the horizon as a fraction of the image height from the top (0..1); below it lies the
  // ground, which is separated from the trunk by GrabCut. Negative: estimated from the sky model.
  double horizon = -1.0;
  // Half-width in pixels of the unknown band around hard (GrabCut) edges; 0: 1 px per 256 px of
  // the shorter image side, at least 1.
  int band_radius = 0;
  // `band_radius`, or the automatic width for a width x height photo.
  int BandRadius(int width, int height) const;
  // Fraction of the image height whose rows seed the sky colour model.
  double sky_seed_rows = 0.08;
  // Spread (Lab units) of the top rows around the smooth sky model above which they are taken for
  // textured ground: the photo shows no sky and the tree is cut from the ground by GrabCut alone.
  double max_sky_sigma = 6.0;
  // Lab distance below which a pixel is pure sky, whatever the spread of the sky model.
  double sky_tolerance = 4.0;
  // The leaf colour behind a mixed pixel is taken from the pixels within `leaf_search` (fraction of
  // the shorter side) whose distance from the sky is at least `leaf_purity` times the largest.
  double leaf_search = 0.05;
  double leaf_purity = 0.9;
  // Treat bright, nearly grey pixels above the horizon as background (clouds).
  bool clouds = true;
  // GrabCut settles the edges of the trunk below the horizon, after a nearest-neighbour colour
  // test (bark above the ground versus ground away from the trunk) found it; off: the test alone.
  bool ground_grabcut = true;
  // Below the horizon, pixels of GrabCut's tree whose colour is within `gap_distance` (Lab) of
  // the photo's own ground are left to the solver: GrabCut closes the gaps of a sparse crown
  // (35° ring, each photo alone: young oak MSE 0.098 -> 0.0014, oak 0.0023 -> 0.0005). 10 keeps
  // more of the aspen's thin branches than 16 (held-out recall 0.840 against 0.819).
  bool open_gaps = true;
  double gap_distance = 10.0;
  // Trunk separation runs on a copy whose longer side is at most this (GrabCut is slow on photos).
  int grabcut_max_side = 512;
  // Guided filter radius (pixels at 256 px, scaled with the image) and regularization.
  int guided_radius = 2;
  double guided_epsilon = 1e-4;
  // infoFlow runs on tiles of at most this many unknown-band pixels (its cost grows faster than
  // linearly with the unknown count).
  int infoflow_tile = 256;

  // Throws Error naming the offending field.
  void Check() const;
};

}  // namespace voltree
