#include "pipeline/reconstruction_guard.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "reconstruct/billboard_raster.h"

namespace voltree {
namespace {

// Mean alpha (0..1) of the matte's pixels [x0, x1) x [y0, y1), at least one pixel.
double MeanAlpha(const Image8& matte, int x0, int y0, int x1, int y1) {
  x1 = std::max(x1, x0 + 1);
  y1 = std::max(y1, y0 + 1);
  uint64_t sum = 0;
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x) sum += matte.at(x, y);
  return double(sum) / (255.0 * (x1 - x0) * (y1 - y0));
}

}  // namespace

void ReproductionOptions::Check() const {
  if (max_side < 8) Fail("reproduction check size must be at least 8, got ", max_side);
  if (!(covered_alpha > 0 && covered_alpha < 1)) Fail("covered alpha must be in (0, 1), got ", covered_alpha);
  if (!(min_recall >= 0 && min_recall <= 1)) Fail("min recall must be in [0, 1], got ", min_recall);
  if (!(min_precision >= 0 && min_precision <= 1)) Fail("min precision must be in [0, 1], got ", min_precision);
}

std::vector<ViewReproduction> MeasureReproduction(const Volume& volume, const std::vector<View>& views,
                                                  const std::vector<Image8>& mattes,
                                                  const ReproductionOptions& options) {
  options.Check();
  if (views.size() != mattes.size())
    Fail("reproduction check: ", views.size(), " views but ", mattes.size(), " mattes");
  if (volume.levels.empty()) Fail("reproduction check: the volume has no levels");
  const int level = int(volume.levels.size()) - 1;

  std::vector<ViewReproduction> result(views.size());
  tbb::parallel_for(size_t(0), views.size(), [&](size_t v) {
    const View& view = views[v];
    const Image8& matte = mattes[v];
    const auto own = std::find_if(volume.views.begin(), volume.views.end(),
                                  [&](const VolumeView& candidate) { return candidate.name == view.name; });
    if (own == volume.views.end()) Fail("reproduction check: the volume has no view '", view.name, "'");
    // The finest level's billboards of this view, drawn as the renderer draws them here.
    const double shrink = std::min(1.0, double(options.max_side) / std::max(matte.width, matte.height));
    View small = view;
    small.camera = view.camera.Resized(std::max(1, int(std::lround(matte.width * shrink))),
                                       std::max(1, int(std::lround(matte.height * shrink))));
    const ViewBlend alone{int(own - volume.views.begin()), -1, 1, 0};
    const ImageF drawn = CompositeLayers(RasterizeLevel(volume, level, small, alone, options.billboard_scale),
                                         volume.levels[level].texels);
    const int width = small.camera.width, height = small.camera.height;
    size_t both = 0, in_matte = 0, in_volume = 0;
    for (int y = 0; y < height; ++y)
      for (int x = 0; x < width; ++x) {
        const bool volume_covers = drawn.at(x, y, 3) > options.covered_alpha;
        const bool matte_covers =
            MeanAlpha(matte, x * matte.width / width, y * matte.height / height, (x + 1) * matte.width / width,
                      (y + 1) * matte.height / height) > options.covered_alpha;
        both += volume_covers && matte_covers;
        in_matte += matte_covers;
        in_volume += volume_covers;
      }
    result[v] = {view.name, in_matte ? double(both) / double(in_matte) : 1.0,
                 in_volume ? double(both) / double(in_volume) : 0.0};
  });
  return result;
}

void CheckReproduction(const std::vector<ViewReproduction>& views, const ReproductionOptions& options) {
  options.Check();
  if (views.empty()) return;
  double recall = 0, precision = 0;
  for (const ViewReproduction& view : views) {
    recall += view.recall;
    precision += view.precision;
  }
  recall /= double(views.size());
  precision /= double(views.size());
  if (recall >= options.min_recall && precision >= options.min_precision) return;
  std::vector<ViewReproduction> worst = views;
  std::sort(worst.begin(), worst.end(), [](const ViewReproduction& a, const ViewReproduction& b) {
    return std::min(a.recall, a.precision) < std::min(b.recall, b.precision);
  });
  std::string list;
  for (size_t i = 0; i < worst.size() && i < 8; ++i)
    list += Str("\n  ", worst[i].name, ": recall ", std::round(worst[i].recall * 1000) / 1000, ", precision ",
                std::round(worst[i].precision * 1000) / 1000);
  Fail("the reconstruction does not reproduce its own input mattes (mean recall ", std::round(recall * 1000) / 1000,
       ", precision ", std::round(precision * 1000) / 1000, "; limits ", options.min_recall, " and ",
       options.min_precision, "), so no asset was written. Worst photos:", list,
       "\nThe mattes or the cameras are likely wrong: check the mattes of those photos and the bounds in "
       "scene.json; delete mattes/ or sparse/ to compute them again. volume/ is kept for inspection");
}

}  // namespace voltree
