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
#include "reconstruct/volume_io.h"
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
      TraverseGrid(window, ray, 0.0, std::numeric_limits<double>::infinity(), [&](int i, int j, int k, double l, double) {
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
  int views = 0;
  double rgb = 0, alpha = 0, precision = 0, recall = 0;
  void Add(const ViewMetrics& m) {
    ++views, rgb += m.rgb_psnr, alpha += m.alpha_psnr, precision += m.precision, recall += m.recall;
  }
  BudgetRow Row(std::string step, ViewSet set, bool colour) const {
    const double n = std::max(views, 1);
    return {std::move(step), set, views, colour ? rgb / n : std::numeric_limits<double>::quiet_NaN(), alpha / n,
            precision / n, recall / n};
  }
};

}  // namespace

std::vector<BudgetRow> MeasureErrorBudget(const fs::path& workspace, const VtreeAsset& asset,
                                          const std::vector<TruthView>& held_out, const std::vector<TruthView>& inputs,
                                          const ImageMetricsOptions& metrics, Progress& progress) {
  const fs::path volume_path = workspace / "volume";
  if (!fs::is_directory(volume_path))
    Fail(volume_path.string(), ": no volume; the error budget needs the reconstruction ('voltree reconstruct ",
         workspace.string(), "')");
  const Volume volume = ReadVolume(volume_path);
  const int finest = int(volume.levels.size()) - 1;
  if (asset.levels.size() != volume.levels.size() || asset.views.size() != volume.views.size() ||
      asset.levels.back().billboards.size() != volume.levels.back().billboards.size())
    Fail(volume_path.string(), " does not match the asset (levels, views or billboards differ): rebuild the asset "
         "from this volume ('voltree compress --force') before measuring its budget");

  // The codewords before DXT5: recompress with the asset's recorded options (same codebooks).
  CompressOptions options;
  const nlohmann::json& recorded = asset.provenance.value("options", nlohmann::json::object());
  options.colour_codebook = recorded.value("codebook", int(asset.colour_codebook_size));
  options.alpha_codebook = recorded.value("alpha_codebook", int(asset.alpha_codebook_size));
  options.space = recorded.value("space", std::string("lab")) == "rgb" ? ColourSpace::kRgb : ColourSpace::kLab;
  options.rule = recorded.value("gla", std::string("modified")) == "classic" ? CodewordRule::kCentroid
                                                                             : CodewordRule::kClosestMember;
  options.alpha_weighted = recorded.value("alpha_weighted", false);
  options.tolerance = recorded.value("tolerance", options.tolerance);
  options.max_iterations = recorded.value("max_iterations", options.max_iterations);
  options.seed = recorded.value("seed", options.seed);
  options.black_threshold = recorded.value("black_threshold", options.black_threshold);
  progress.Say("budget", "recompressing the volume for the codewords before DXT5");
  const CompressResult again = CompressVolume(volume, options);
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
    Sum sums[4];
    for (const TruthView& view : views) {
      const Image8 truth = LoadTruthImage(view);
      ImageMetricsOptions m = metrics;
      m.truth_premultiplied = view.premultiplied;
      m.render_premultiplied = true;
      sums[0].Add(CompareViews(VolumeAlpha(volume, view.camera), truth, m));
      const ViewPair pair = SelectViews(asset.views, centre, view.camera.pose.Center());
      const ViewBlend blend{pair.first, pair.second, pair.first_weight, pair.second_weight};
      const LayerImage layers = RasterizeLevel(volume, finest, view.camera, blend, 1.0);
      for (int s = 0; s < 3; ++s) sums[s + 1].Add(CompareViews(ToImage8(CompositeLayers(layers, texels[s])), truth, m));
      progress.Say("budget", Str(ViewSetName(set), " ", view.camera.name));
    }
    const char* steps[4] = {"volume", "billboards", "vq", "dxt5"};
    for (int s = 0; s < 4; ++s)
      if (sums[s].views) rows.push_back(sums[s].Row(steps[s], set, s > 0));
  }
  return rows;
}

void AppendLodRows(const LevelMetricsTable& table, std::vector<BudgetRow>* rows) {
  for (ViewSet set : {ViewSet::kInput, ViewSet::kHeldOut}) {
    const MetricsReport& report = table.Overall(set);
    if (report.views.empty()) continue;
    Sum sum;
    for (const NamedViewMetrics& view : report.views) sum.Add(view.metrics);
    rows->push_back(sum.Row("lod", set, true));
  }
}

std::string BudgetTable(const std::vector<BudgetRow>& rows) {
  std::string out = "step        views     count  RGB PSNR  alpha PSNR      P      R\n";
  for (const BudgetRow& r : rows) {
    char line[160];
    std::snprintf(line, sizeof line, "%-11s %-9s %5d  %8s  %10s  %.3f  %.3f\n", r.step.c_str(), ViewSetName(r.set),
                  r.views, std::isnan(r.rgb_psnr) ? "-" : FixedDecimals(r.rgb_psnr, 2).c_str(),
                  FixedDecimals(r.alpha_psnr, 2).c_str(), r.precision, r.recall);
    out += line;
  }
  return out;
}

}  // namespace voltree
