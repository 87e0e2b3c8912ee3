#include "capture/matte/trimap.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <opencv2/imgproc.hpp>

#include "capture/matte/fill.h"
#include "capture/matte/grabcut.h"
#include "capture/matte/sky_estimate.h"

namespace voltree::matte {

namespace {

cv::Mat Weight(const cv::Mat& mask8) {
  cv::Mat weight;
  mask8.convertTo(weight, CV_32F, 1.0 / 255.0);
  return weight;
}

cv::Mat Disk(int radius) {
  return cv::getStructuringElement(cv::MORPH_ELLIPSE, cv::Size(2 * radius + 1, 2 * radius + 1));
}

// Keeps the parts of `tree` (CV_8U) that touch row `top`: the trunk hangs from the tree above;
// dark patches of ground that GrabCut took for bark do not.
cv::Mat KeepConnectedToRow(const cv::Mat& tree, int top) {
  cv::Mat labels;
  const int count = cv::connectedComponents(tree, labels, 8, CV_32S);
  std::vector<char> keep(count, 0);
  for (int x = 0; x < tree.cols; ++x) keep[labels.at<int>(top, x)] = tree.at<uint8_t>(top, x) != 0;
  cv::Mat kept = cv::Mat::zeros(tree.size(), CV_8U);
  for (int y = 0; y < tree.rows; ++y)
    for (int x = 0; x < tree.cols; ++x) kept.at<uint8_t>(y, x) = keep[labels.at<int>(y, x)] ? 255 : 0;
  return kept;
}

std::vector<cv::Vec3f> Samples(const cv::Mat& lab, const cv::Mat& mask, int max_count) {
  const int count = cv::countNonZero(mask);
  const int stride = std::max(1, count / std::max(1, max_count));
  std::vector<cv::Vec3f> samples;
  int seen = 0;
  for (int y = 0; y < lab.rows; ++y)
    for (int x = 0; x < lab.cols; ++x)
      if (mask.at<uint8_t>(y, x) && seen++ % stride == 0) samples.push_back(lab.at<cv::Vec3f>(y, x));
  return samples;
}

float NearestSquared(const cv::Vec3f& p, const std::vector<cv::Vec3f>& samples) {
  float best = 1e30f;
  for (const cv::Vec3f& s : samples) {
    const cv::Vec3f d = p - s;
    best = std::min(best, d.dot(d));
  }
  return best;
}

// Below the horizon (rows from `ground_start`; `horizon` is the true horizon row): CV_8U 255 where
// the ground region is tree (the trunk). Every ground point lies below the horizon, so the trunk
// reaches from the tree above down past the horizon. A nearest-neighbour colour test against the
// bark just above the ground and the ground away from the trunk gives a first mask; GrabCut then
// settles its edges (optional); only parts connected to the tree above are kept.
cv::Mat SeparateTrunkFromGround(const cv::Mat& rgb, const cv::Mat& alpha, const cv::Mat& sky, int ground_start,
                                int horizon, const MatteOptions& options) {
  const int rows = rgb.rows, cols = rgb.cols;
  const int touch = std::max(2, rows / 100);
  const int top = std::max(0, ground_start - touch);
  // Work on a reduced copy of the strip from `top` down: the colour test and GrabCut are slow.
  const double scale = std::min(1.0, double(options.grabcut_max_side) / std::max(rows - top, cols));
  const cv::Size size(std::max(1, int(std::lround(cols * scale))), std::max(1, int(std::lround((rows - top) * scale))));
  cv::Mat strip, strip_alpha, strip_lab, strip_sky;
  cv::resize(sky.rowRange(top, rows), strip_sky, size, 0, 0, cv::INTER_NEAREST);
  cv::resize(rgb.rowRange(top, rows), strip, size, 0, 0, cv::INTER_AREA);
  cv::resize(alpha.rowRange(top, rows), strip_alpha, size, 0, 0, cv::INTER_AREA);
  strip.convertTo(strip_lab, CV_32F, 1.0 / 255.0);
  cv::cvtColor(strip_lab, strip_lab, cv::COLOR_RGB2Lab);
  const int start = std::clamp(int(std::lround((ground_start - top) * scale)), 1, size.height - 1);
  const int below_horizon = std::clamp(int(std::lround((horizon - top) * scale)) + 1, start, size.height - 1);

  // Bark: solid tree pixels just above the ground region. Ground: below the horizon, away from the
  // columns the tree comes down in.
  const cv::Mat bark_mask = (strip_alpha > 0.9f) & RowsAbove(size.height, size.width, start);
  std::vector<char> trunk_column(size.width, 0);
  for (int x = 0; x < size.width; ++x)
    for (int y = 0; y < start; ++y) trunk_column[x] |= strip_alpha.at<float>(y, x) > 0.5f;
  cv::Mat ground_mask = ~RowsAbove(size.height, size.width, below_horizon);
  const int slack = std::max(2, size.width / 50);
  for (int x = 0; x < size.width; ++x)
    if (trunk_column[x]) ground_mask.colRange(std::max(0, x - slack), std::min(size.width, x + slack + 1)).setTo(0);
  const std::vector<cv::Vec3f> bark = Samples(strip_lab, bark_mask, 256);
  // The rows between the ground region's start and the horizon still show sky.
  const std::vector<cv::Vec3f> ground = Samples(strip_lab, ground_mask | strip_sky, 1024);
  if (bark.empty() || ground.empty()) return cv::Mat::zeros(rgb.size(), CV_8U);

  cv::Mat barkness(size, CV_32F, cv::Scalar(0.0f));
  for (int y = start; y < size.height; ++y)
    for (int x = 0; x < size.width; ++x) {
      const cv::Vec3f p = strip_lab.at<cv::Vec3f>(y, x);
      const float to_bark = NearestSquared(p, bark), to_ground = NearestSquared(p, ground);
      barkness.at<float>(y, x) = strip_sky.at<uint8_t>(y, x) ? 0.0f : to_ground / (to_ground + to_bark + 1e-6f);
    }
  cv::blur(barkness, barkness, cv::Size(3, 3));  // ground texture is grainy; bark is a region
  cv::Mat tree = barkness > 0.5f;
  tree.rowRange(0, start).setTo(0);
  tree = KeepConnectedToRow(tree | (RowsAbove(size.height, size.width, start) & (strip_alpha > 0.5f)), start - 1);
  tree.rowRange(0, start).setTo(0);

  if (options.ground_grabcut && cv::countNonZero(tree) > 0) {
    cv::Mat mask(size, CV_8U);
    for (int y = 0; y < size.height; ++y)
      for (int x = 0; x < size.width; ++x) {
        const float a = strip_alpha.at<float>(y, x);
        // Confident colour-test answers are fixed; GrabCut decides the rest.
        const float b = barkness.at<float>(y, x);
        const bool in_tree = tree.at<uint8_t>(y, x) != 0;
        mask.at<uint8_t>(y, x) = y < start ? (a > 0.9f    ? cv::GC_FGD
                                              : a < 0.02f ? cv::GC_BGD
                                                          : cv::GC_PR_BGD)
                                 : in_tree ? (b > 0.75f ? cv::GC_FGD : cv::GC_PR_FGD)
                                           : (b < 0.25f ? cv::GC_BGD : cv::GC_PR_BGD);
      }
    tree = KeepConnectedToRow(GrabCutForeground(strip, mask, 3, options.grabcut_max_side), start - 1);
    tree.rowRange(0, start).setTo(0);
  }
  cv::Mat full = cv::Mat::zeros(rgb.size(), CV_8U);
  cv::Mat strip_tree;
  cv::resize(tree, strip_tree, cv::Size(cols, rows - top), 0, 0, cv::INTER_NEAREST);
  strip_tree.copyTo(full.rowRange(top, rows));
  full.rowRange(0, ground_start).setTo(0);
  return full;
}

// GrabCut's smoothness closes a sparse crown: the ground seen through its gaps, and patches of
// ground next to the tree, come out as tree. CV_8U 255 where a pixel of `tree` (CV_8U) shows a
// colour within `tolerance` (Lab) of this photo's own ground (`ground`, away from the tree). Empty
// when that leaves less than a tenth of the tree: then nothing would seed the solver.
cv::Mat GroundColouredInTree(const cv::Mat& lab, const cv::Mat& tree, const cv::Mat& ground, float tolerance) {
  cv::Mat coloured = cv::Mat::zeros(tree.size(), CV_8U);
  const std::vector<cv::Vec3f> ground_colours = Samples(lab, ground & ~tree, 1024);
  if (ground_colours.empty()) return coloured;
  for (int y = 0; y < lab.rows; ++y)
    for (int x = 0; x < lab.cols; ++x)
      if (tree.at<uint8_t>(y, x) && NearestSquared(lab.at<cv::Vec3f>(y, x), ground_colours) < tolerance * tolerance)
        coloured.at<uint8_t>(y, x) = 255;
  if (10 * (cv::countNonZero(tree) - cv::countNonZero(coloured)) < cv::countNonZero(tree)) coloured.setTo(0);
  return coloured;
}

// No sky in the photo (a camera looking down): the background is ground everywhere. GrabCut
// from the frame: a border strip is certain ground, the rest probably tree. CV_8U 255 = tree.
cv::Mat CutFromGround(const cv::Mat& rgb, const MatteOptions& options) {
  const int border = std::max(2, std::min(rgb.rows, rgb.cols) * 3 / 100);
  if (rgb.rows <= 3 * border || rgb.cols <= 3 * border) return cv::Mat::zeros(rgb.size(), CV_8U);
  cv::Mat labels(rgb.size(), CV_8U, cv::Scalar(cv::GC_BGD));
  labels(cv::Rect(border, border, rgb.cols - 2 * border, rgb.rows - 2 * border)).setTo(cv::GC_PR_FGD);
  return GrabCutForeground(rgb, labels, 5, options.grabcut_max_side);
}

}  // namespace

cv::Mat LowContrast(const cv::Mat& background, const cv::Mat& foreground, float min_contrast) {
  cv::Mat difference = foreground - background, squared, contrast;
  cv::transform(difference.mul(difference), squared, cv::Matx13f(1, 1, 1));
  return squared < min_contrast * min_contrast;
}

cv::Mat ProjectAlpha(const cv::Mat& image, const cv::Mat& background, const cv::Mat& foreground,
                     const cv::Mat& fallback, float min_contrast) {
  cv::Mat alpha(image.size(), CV_32F);
  for (int y = 0; y < image.rows; ++y)
    for (int x = 0; x < image.cols; ++x) {
      const cv::Vec3f i = image.at<cv::Vec3f>(y, x), b = background.at<cv::Vec3f>(y, x),
                      f = foreground.at<cv::Vec3f>(y, x);
      const cv::Vec3f fb = f - b;
      const float contrast = fb.dot(fb);
      const float a = contrast > min_contrast * min_contrast ? (i - b).dot(fb) / contrast : fallback.at<float>(y, x);
      alpha.at<float>(y, x) = std::clamp(a, 0.0f, 1.0f);
    }
  return alpha;
}

Segmentation SegmentTree(const cv::Mat& rgb, const MatteOptions& options) {
  CV_Assert(rgb.type() == CV_8UC3);
  const int rows = rgb.rows, cols = rgb.cols;
  cv::Mat rgbf, lab;
  rgb.convertTo(rgbf, CV_32F, 1.0 / 255.0);
  cv::cvtColor(rgbf, lab, cv::COLOR_RGB2Lab);

  const SkyEstimate estimate = EstimateSky(lab, options);
  const SkyModel& sky = estimate.model;
  const cv::Mat& clouds = estimate.clouds;
  const cv::Mat& sky_pixels = estimate.pixels;
  int horizon = estimate.horizon;

  Segmentation result;
  result.horizon_row = horizon;
  // The rows just above the horizon mix sky and ground: the colour alpha would call them tree, so
  // they go with the ground, to GrabCut.
  horizon = estimate.MixedRowsStart();
  result.sky_sigma = sky.sigma;
  result.alpha = cv::Mat::zeros(rgb.size(), CV_32F);
  cv::Mat low_contrast = cv::Mat::zeros(rgb.size(), CV_8U);
  const cv::Mat above = RowsAbove(rows, cols, horizon);
  if (horizon > 0 && sky.valid()) {
    // Background behind every pixel above the horizon: the model, or the cloud itself.
    cv::Mat background_lab = sky.Predict(rgb.size()), background;
    cv::cvtColor(background_lab, background, cv::COLOR_Lab2RGB);
    rgbf.copyTo(background, clouds);
    // Leaf colour near each pixel, from the purest tree pixels around: those nearly as far from
    // the sky as the farthest one within the search radius (mixed edge pixels would bias it
    // towards the sky and push alpha to 1).
    const double tolerance = estimate.Tolerance(options);
    cv::Mat distance = SkyDistance(lab, sky);
    distance.setTo(0.0f, clouds | ~above);
    const int search = std::max(2, int(std::lround(options.leaf_search * std::min(rows, cols))));
    cv::Mat farthest;
    cv::dilate(distance, farthest, Disk(search));
    const cv::Mat pure = (distance >= options.leaf_purity * farthest) & (distance > 2.0 * tolerance);
    const cv::Mat hard = Weight((distance > 2.0 * tolerance) & above);
    const cv::Mat leaf = PushPullFill(rgbf, Weight(pure));
    cv::Mat alpha = ProjectAlpha(rgbf, background, leaf, hard);
    low_contrast = LowContrast(background, leaf) & above;
    alpha.setTo(0.0f, sky_pixels & ~(alpha > 0.5f));
    alpha.copyTo(result.alpha, above);
  }

  // Trimap above the horizon: colour alpha decides, fractional values are unknown.
  result.trimap = cv::Mat(rgb.size(), CV_8U, cv::Scalar(128));
  result.trimap.setTo(0, (result.alpha <= 0.02f) & above);
  result.trimap.setTo(255, (result.alpha >= 0.98f) & above);
  result.solve = (result.trimap == 128) & low_contrast;

  if (horizon < rows) {
    const cv::Mat ground = ~above;
    const cv::Mat tree =
        horizon > 0 ? SeparateTrunkFromGround(rgb, result.alpha, sky_pixels, horizon, result.horizon_row, options)
                    : CutFromGround(rgb, options);
    result.alpha.setTo(1.0f, tree);
    // Hard GrabCut edges are uncertain within the band radius.
    const int radius = options.BandRadius(cols, rows);
    cv::Mat inside, outside;
    cv::erode(tree, inside, Disk(radius));
    cv::dilate(tree, outside, Disk(radius));
    cv::Mat ground_trimap(rgb.size(), CV_8U, cv::Scalar(128));
    ground_trimap.setTo(0, outside == 0);
    ground_trimap.setTo(255, inside);
    if (options.open_gaps) {
      // Left to the solver, not called background: where the colour test is wrong (bark like
      // soil) the tree around it still pulls alpha up.
      const cv::Mat gaps = GroundColouredInTree(lab, inside, (outside == 0) & ground, float(options.gap_distance));
      ground_trimap.setTo(128, gaps);
    }
    ground_trimap.copyTo(result.trimap, ground);
    result.solve.setTo(255, (ground_trimap == 128) & ground);
  }
  return result;
}

}  // namespace voltree::matte
