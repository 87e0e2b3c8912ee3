// Internal to the matting files: the photos nearest a view, and where a view's pixels land in one
// of them when what they show is known to lie far away or on the ground.
#pragma once

#include <opencv2/core.hpp>
#include <vector>

#include "core/camera.h"

namespace voltree::matte {

// The views nearest to `target` by camera centre, nearest first, at most `count`.
std::vector<size_t> NearestViews(const std::vector<voltree::View>& views, size_t target, int count);

// What a pixel is assumed to show: the distant backdrop (only its direction matters) or the
// ground, the plane z = ground_z of the views' frame.
enum class Depth { kFar, kGround };

// Where each pixel of `from` lands in `to` under `depth`, as cv::remap maps (CV_32F, pixel centres
// at integers); -1 where the hypothesis says nothing (the ground above the horizon, a point
// behind the camera, the far backdrop well below the horizon, where the ground is in the way)
// and outside `roi` (the whole image when empty: a caller that needs a few pixels pays for those).
void DepthMaps(const voltree::View& from, const voltree::View& to, Depth depth, double ground_z, cv::Mat* map_x,
               cv::Mat* map_y, cv::Rect roi = {});

}  // namespace voltree::matte
