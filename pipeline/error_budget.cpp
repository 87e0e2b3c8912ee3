#include "pipeline/error_budget.h"

#include <tbb/parallel_for.h>

#include <cmath>
#include <limits>

#include "compress/compress_volume.h"
#include "core/error.h"
#include "core/fixed.h"
#include "reconstruct/billboard_raster.h"
#include "reconstruct/dda.h"
#include "reconstruct/grid.h"
#include "core/volume_io.h"
#include "render/view_selection.h"

namespace voltree {
namespace fs = std::filesystem;
namespace {

// Premultiplied RGBA floats in [0, 1] -> premultiplied RGBA8.
Image8 ToImage8(const ImageF& image) {
  Image8 out(image.width, image.height, 4);
  for (size_t i = 0; i < image.pixels.size(); ++i)
    out.pixels[i] = uint8_t(std::lround(std::clamp(image.pixels[i], 0.0f, 1.0f) * 255.0f));
  return out;
}

// (a): 1 - exp(-sum sigma l) along each pixel's ray through the finest level; no colour.
Image8 VolumeAlpha(const Volume& volume, const View& camera) {
  const int finest = int(volume.levels.size()) - 1;
  const VolumeLevel& level = volume.levels[finest];
  const LevelCells cells(level.resolution, level.cells);
  const GridWindow window{volume.origin, volume.CellSize(finest), cells.box_min(), cells.box_max()};
  Image8 out(camera.camera.width, camera.camera.height, 4);
  tbb::parallel_for(0, out.height, [&](int y) {
    for (int x = 0; x < out.width; ++x) {
      const Ray ray{camera.pose.Center(), camera.PixelRay({x + 0.5, y + 0.5})};
      double depth = 0;
      TraverseGrid(window, ray, 0.0, std::numeric_limits<double>::infinity(),
                   [&](int i, int j, int k, double l, double) {
                     const int32_t c = cells.Find(i, j, k);
                     if (c >= 0) depth += level.density[c] * l;
                     return true;
                   });
      out.at(x, y, 3) = uint8_t(std::lround(255 * (1 - std::exp(-depth))));
    }
  });
  return out;
}

std::vector<float> ToFloat(const uint8_t* begin, size_t count) {
  std::vector<float> out(count);
  for (size_t i = 0; i < count; ++i) out[i] = begin[i] / 255.0f;
  return out;
}

// Mean metrics over views, one accumulator per step and set.
struct Sum {
  int views = 0, parted = 0;
  double rgb = 0, alpha = 0, precision = 0, recall = 0, bark = 0, leaf = 0;
  void Add(const ViewMetrics& m, const Image8& render, const Image8& parts, float threshold) {
    ++views, rgb += m.rgb_psnr, alpha += m.alpha_psnr, precision += m.precision, recall += m.recall;
    if (parts.empty()) return;
    const double b = PartRecall(render, parts, 0, threshold), l = PartRecall(render, parts, 1, threshold);
    if (std::isnan(b) || std::isnan(l)) return;  // a view without one of the parts counts for neither
    ++parted, bark += b, leaf += l;
  }
  BudgetRow Row(std::string step, ViewSet set, bool colour) const {
    const double n = std::max(views, 1), nan = std::numeric_limits<double>::quiet_NaN();
    return {std::move(step),
            set,
            views,
            colour ? rgb / n : nan,
            alpha / n,
            precision / n,
            recall / n,
            parted ? bark / parted : nan,
            parted ? leaf / parted : nan};
  }
};

}  // namespace

double PartRecall(const Image8& render, const Image8& parts, int channel, float coverage_threshold) {
  if (render.width != parts.width || render.height != parts.height || parts.channels < 2)
    Fail("parts mask is ", parts.width, "x", parts.height, "x", parts.channels, ", expected ", render.width, "x",
         render.height, " RGB");
  const int covered = int(std::lround(255 * coverage_threshold));
  int64_t shown = 0, found = 0;
  for (int y = 0; y < parts.height; ++y)
    for (int x = 0; x < parts.width; ++x)
      if (parts.at(x, y, channel) >= 128) {
        ++shown;
        found += render.at(x, y, render.channels - 1) > covered;
      }
  return shown ? double(found) / double(shown) : std::numeric_limits<double>::quiet_NaN();
}

std::vector<BudgetRow> MeasureErrorBudget(const fs::path& workspace, const VtreeAsset& asset,
                                          const std::vector<TruthView>& held_out, const std::vector<TruthView>& inputs,
                                          const ImageMetricsOptions& metrics, const LodRenderer& render_lod,
                                          Progress& progress) {
  const fs::path volume_path = workspace / "volume";
  if (!fs::is_directory(volume_path))
    Fail(volume_path.string(), ": no volume; the error budget needs the reconstruction ('voltree reconstruct ",
         workspace.string(), "')");
  const Volume volume = ReadVolume(volume_path);
  const int finest = int(volume.levels.size()) - 1;
  if (asset.levels.size() != volume.levels.size() || asset.views.size() != volume.views.size() ||
      asset.levels.back().billboards.size() != volume.levels.back().billboards.size())
    Fail(volume_path.string(),
         " does not match the asset (levels, views or billboards differ): rebuild the asset "
         "from this volume ('voltree compress --force') before measuring its budget");

  // The codewords before DXT5: recompress with the asset's recorded options (same codebooks). What
  // older releases did not record: the asset's codebook sizes, one modified rule, plain distances.
  CompressOptions absent;
  absent.colour_codebook = int(asset.colour_codebook_size);
  absent.alpha_codebook = int(asset.alpha_codebook_size);
  absent.colour_rule = CodewordRule::kClosestMember;
  absent.alpha_weighted = false;
  const CompressOptions options =
      CompressOptions::FromJson(asset.provenance.value("options", nlohmann::json::object()), absent);
  progress.Say("budget", "recompressing the volume for the codewords before DXT5");
  const CompressResult again = CompressVolume(volume, options);
  if (again.asset.atlas.dxt5 != asset.atlas.dxt5)
    Fail(volume_path.string(),
         " recompressed with the options the asset records gives other codewords than the asset's, so the vq "
         "step cannot be measured: rebuild the asset from this volume ('voltree compress --force')");
  std::vector<CodewordUse> uses;
  for (const auto& level : again.asset.levels)
    for (const auto& b : level.billboards) uses.push_back({b.colour, b.alpha});
  const std::vector<uint8_t> vq =
      DecodeBillboardsFromCodewords(again.stats.colour_rgb, again.stats.alpha_bytes, volume.texels, uses);
  const std::vector<uint8_t> dxt5 = DecodeBillboardsFromAtlas(asset);
  // Both are concatenated over the levels; the finest level's billboards come last.
  const size_t finest_bytes = volume.levels[finest].texels.size();
  if (vq.size() < finest_bytes || dxt5.size() < finest_bytes) Fail("budget: decoded billboards are too few");
  const std::vector<float> texels[3] = {TexelsAsFloat(volume.levels[finest]),
                                        ToFloat(vq.data() + vq.size() - finest_bytes, finest_bytes),
                                        ToFloat(dxt5.data() + dxt5.size() - finest_bytes, finest_bytes)};

  const Eigen::Vector3d centre = volume.origin + Eigen::Vector3d::Constant(0.5 * volume.size);
  std::vector<BudgetRow> rows;
  for (ViewSet set : {ViewSet::kInput, ViewSet::kHeldOut}) {
    const std::vector<TruthView>& views = set == ViewSet::kInput ? inputs : held_out;
    Sum sums[5];
    for (const TruthView& view : views) {
      const Image8 truth = LoadTruthImage(view);
      const Image8 parts = view.parts.empty() ? Image8() : ReadImage8(view.parts, 3);
      ImageMetricsOptions m = metrics;
      m.truth_premultiplied = view.premultiplied;
      m.render_premultiplied = true;
      const float threshold = metrics.coverage_threshold;
      const Image8 volume_alpha = VolumeAlpha(volume, view.camera);
      sums[0].Add(CompareViews(volume_alpha, truth, m), volume_alpha, parts, threshold);
      const ViewPair pair = SelectViews(asset.views, centre, view.camera.pose.Center());
      const ViewBlend blend{pair.first, pair.second, pair.first_weight, pair.second_weight};
      const LayerImage layers = RasterizeLevel(volume, finest, view.camera, blend, 1.0);
      for (int s = 0; s < 3; ++s) {
        const Image8 render = ToImage8(CompositeLayers(layers, texels[s]));
        sums[s + 1].Add(CompareViews(render, truth, m), render, parts, threshold);
      }
      m.render_premultiplied = false;
      const Image8 lod = render_lod(view.camera);
      sums[4].Add(CompareViews(lod, truth, m), lod, parts, threshold);
      progress.Say("budget", Str(ViewSetName(set), " ", view.camera.name));
    }
    const char* steps[5] = {"volume", "billboards", "vq", "dxt5", "lod"};
    for (int s = 0; s < 5; ++s)
      if (sums[s].views) rows.push_back(sums[s].Row(steps[s], set, s > 0));
  }
  return rows;
}

std::string BudgetTable(const std::vector<BudgetRow>& rows) {
  std::string out = "step        views     count  RGB PSNR  alpha PSNR      P      R  bark R  leaf R\n";
  auto optional = [](double value, int digits) {
    return std::isnan(value) ? std::string("-") : FixedDecimals(value, digits);
  };
  for (const BudgetRow& r : rows) {
    char line[200];
    std::snprintf(line, sizeof line, "%-11s %-9s %5d  %8s  %10s  %.3f  %.3f  %6s  %6s\n", r.step.c_str(),
                  ViewSetName(r.set), r.views, optional(r.rgb_psnr, 2).c_str(), FixedDecimals(r.alpha_psnr, 2).c_str(),
                  r.precision, r.recall, optional(r.bark_recall, 3).c_str(), optional(r.leaf_recall, 3).c_str());
    out += line;
  }
  return out;
}

}  // namespace voltree
