#include "reconstruct/billboard_fit.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>

#include "core/error.h"
#include "core/image_resample.h"
#include "reconstruct/billboard_raster.h"

namespace voltree {
namespace {

// The photo as premultiplied RGBA floats in [0, 1]: colour from the foreground, alpha from the matte.
ImageF PhotoTarget(const Image8& matte, const Image8& foreground) {
  ImageF out(matte.width, matte.height, 4);
  for (int y = 0; y < matte.height; ++y)
    for (int x = 0; x < matte.width; ++x) {
      for (int c = 0; c < 3; ++c) out.at(x, y, c) = foreground.at(x, y, c) / 255.0f;
      out.at(x, y, 3) = matte.at(x, y) / 255.0f;
    }
  return out;
}

// The camera with its image scaled by `factor` (< 1 shrinks).
View ScaledView(const View& view, double factor) {
  View out = view;
  out.camera = view.camera.Resized(std::max(1, int(std::lround(view.camera.width * factor))),
                                   std::max(1, int(std::lround(view.camera.height * factor))));
  return out;
}

// Photo pixels per texel of `level` at the volume centre's depth in `view`.
double TexelPixels(const Volume& volume, int level, const View& view) {
  const Eigen::Vector3d centre = volume.origin + Eigen::Vector3d::Constant(0.5 * volume.size);
  const double depth = std::max(view.pose.ToCamera(centre).z(), 1e-9);
  const double focal = 0.5 * (view.camera.FocalX() + view.camera.FocalY());
  return focal * volume.CellSize(level) / volume.texels / depth;
}

struct Weights {
  float colour = 1, alpha = 1, prior = 0;
};

// One photo the fit compares with: the layers the view's billboards make there, and the photo at
// that scale. `weight` scales its share of the objective.
struct FitImage {
  LayerImage layers;
  ImageF target;
  float weight = 1;
  double scale = 1;  // photo pixels per pixel of `target`
};

// The objective at x (premultiplied RGBA floats, four per texel); with `gradient` and `diagonal`
// (same size, zeroed here) also its gradient and the diagonal of J^T J plus the prior's share.
struct Objective {
  const std::vector<FitImage>& images;  // images[0]: the view's own photo
  const std::vector<float>& start;
  Weights weights;

  struct Value {
    double total = 0, rgb_sse = 0, alpha_sse = 0;  // the squared errors: the own photo's only
    double own = 0;                                // the own photo's share of the total
  };

  Value operator()(const std::vector<float>& x, std::vector<float>* gradient = nullptr,
                   std::vector<float>* diagonal = nullptr) const {
    Value value;
    if (gradient) gradient->assign(x.size(), 0), diagonal->assign(x.size(), 0);
    for (size_t i = 0; i < images.size(); ++i) {
      double rgb = 0, alpha = 0;
      Accumulate(images[i], x, &rgb, &alpha, gradient, diagonal);
      if (i == 0)
        value.rgb_sse = rgb, value.alpha_sse = alpha, value.own = weights.colour * rgb + weights.alpha * alpha;
      value.total += images[i].weight * (weights.colour * rgb + weights.alpha * alpha);
    }
    for (size_t i = 0; i < x.size(); ++i) {
      const double d = x[i] - start[i];
      value.total += weights.prior * d * d;
      if (gradient) (*gradient)[i] += 2 * weights.prior * float(d), (*diagonal)[i] += weights.prior;
    }
    return value;
  }

  // Squared errors of one image; its weighted share of the gradient and diagonal.
  void Accumulate(const FitImage& fit, const std::vector<float>& x, double* rgb_sse, double* alpha_sse,
                  std::vector<float>* gradient, std::vector<float>* diagonal) const {
    const LayerImage& image = fit.layers;
    const int n = image.texels;
    const size_t dx = n > 1 ? 1 : 0, dy = n > 1 ? size_t(n) : 0;
    const float colour_weight = fit.weight * weights.colour, alpha_weight = fit.weight * weights.alpha;
    std::vector<std::array<float, 4>> samples, behind;
    for (size_t p = 0; p + 1 < image.offsets.size(); ++p) {
      const uint32_t begin = image.offsets[p], end = image.offsets[p + 1];
      const float* want = fit.target.pixels.data() + p * 4;
      samples.resize(end - begin), behind.resize(end - begin);
      std::array<float, 4> colour{0, 0, 0, 0};
      for (uint32_t i = begin; i < end; ++i) {
        samples[i - begin] = SampleLayer(image.layers[i], x.data(), n);
        behind[i - begin] = colour;
        const auto& s = samples[i - begin];
        for (int c = 0; c < 4; ++c) colour[c] = s[c] + (1 - s[3]) * colour[c];
      }
      std::array<float, 4> residual;
      for (int c = 0; c < 4; ++c) residual[c] = colour[c] - want[c];
      *rgb_sse +=
          double(residual[0]) * residual[0] + double(residual[1]) * residual[1] + double(residual[2]) * residual[2];
      *alpha_sse += double(residual[3]) * residual[3];
      if (!gradient || begin == end) continue;
      // Front to back: g = dLoss/d(colour after layer i), front = transmittance in front of it.
      std::array<float, 4> g{2 * colour_weight * residual[0], 2 * colour_weight * residual[1],
                             2 * colour_weight * residual[2], 2 * alpha_weight * residual[3]};
      float front = 1;
      for (uint32_t i = end; i-- > begin;) {
        const auto& s = samples[i - begin];
        const auto& b = behind[i - begin];
        // colour_after = s + (1 - s.a) * behind: d/ds.rgb = 1, d/ds.a = e_a - behind.
        const float gs[4] = {g[0], g[1], g[2], g[3] - (g[0] * b[0] + g[1] * b[1] + g[2] * b[2] + g[3] * b[3])};
        const float f2 = front * front;
        const float h_rgb = colour_weight * f2;
        const float h_alpha =
            f2 * (alpha_weight * (1 - b[3]) * (1 - b[3]) + colour_weight * (b[0] * b[0] + b[1] * b[1] + b[2] * b[2]));
        for (const BillboardTap& tap : image.layers[i].taps) {
          if (tap.weight == 0) continue;
          const float w[4] = {(1 - tap.fx) * (1 - tap.fy), tap.fx * (1 - tap.fy), (1 - tap.fx) * tap.fy,
                              tap.fx * tap.fy};
          const size_t texel[4] = {tap.texel, tap.texel + dx, tap.texel + dy, tap.texel + dx + dy};
          for (int k = 0; k < 4; ++k) {
            const float ww = tap.weight * w[k];
            if (ww == 0) continue;
            float* gt = gradient->data() + texel[k] * 4;
            float* ht = diagonal->data() + texel[k] * 4;
            for (int c = 0; c < 4; ++c) gt[c] += ww * gs[c];
            for (int c = 0; c < 3; ++c) ht[c] += ww * ww * h_rgb;
            ht[3] += ww * ww * h_alpha;
          }
        }
        for (float& gc : g) gc *= 1 - s[3];
        front *= 1 - s[3];
      }
    }
  }
};

// Premultiplied RGBA texels stay valid: 0 <= rgb <= a <= 1.
void Project(std::vector<float>* x) {
  for (size_t i = 0; i < x->size(); i += 4) {
    float* t = x->data() + i;
    t[3] = std::clamp(t[3], 0.0f, 1.0f);
    for (int c = 0; c < 3; ++c) t[c] = std::clamp(t[c], 0.0f, t[3]);
  }
}

double Psnr(double sse, double count) { return sse <= 0 ? 99.0 : 10 * std::log10(count / sse); }

struct JobResult {
  double scale = 1;
  size_t layers = 0, pixels = 0;
  Objective::Value before, after;
  bool diverged = false;
};

// The input views nearest in angle to view v (seen from the volume centre), nearest first.
std::vector<int> NeighbourViews(const Volume& volume, int v, int count) {
  const Eigen::Vector3d centre = volume.origin + Eigen::Vector3d::Constant(0.5 * volume.size);
  const Eigen::Vector3d own = volume.views[v].position - centre;
  std::vector<std::pair<double, int>> angles;
  for (int u = 0; u < int(volume.views.size()); ++u) {
    if (u == v) continue;
    const Eigen::Vector3d other = volume.views[u].position - centre;
    angles.push_back({std::atan2(own.cross(other).norm(), own.dot(other)), u});
  }
  std::sort(angles.begin(), angles.end());
  std::vector<int> out;
  for (int i = 0; i < std::min<int>(count, int(angles.size())); ++i) out.push_back(angles[i].second);
  return out;
}

// The billboards of one view at one level, numbered locally so that the work buffers hold only
// those: level billboard `global[i]` is local billboard i.
struct ViewBillboards {
  std::vector<uint32_t> global;
  std::vector<uint32_t> local;  // level billboard -> local index (meaningful for this view's only)
  size_t per_billboard = 16;    // texels per billboard

  ViewBillboards(const Volume& volume, int level, int v)
      : local(volume.levels[level].billboards.size(), 0), per_billboard(size_t(volume.texels) * volume.texels) {
    const auto& billboards = volume.levels[level].billboards;
    for (uint32_t b = 0; b < billboards.size(); ++b)
      if (billboards[b].view == v) local[b] = uint32_t(global.size()), global.push_back(b);
  }
  // Rewrites the taps of `layers` (which draw only this view) to local texel indices.
  void Renumber(LayerImage* layers) const {
    for (BillboardLayer& layer : layers->layers)
      for (BillboardTap& tap : layer.taps)
        if (tap.weight != 0)
          tap.texel = uint32_t(local[tap.texel / per_billboard] * per_billboard + tap.texel % per_billboard);
  }
  std::vector<float> Gather(const std::vector<float>& level_texels) const {
    std::vector<float> x(global.size() * per_billboard * 4);
    for (size_t b = 0; b < global.size(); ++b)
      std::copy_n(level_texels.data() + global[b] * per_billboard * 4, per_billboard * 4,
                  x.data() + b * per_billboard * 4);
    return x;
  }
  void Scatter(const std::vector<float>& x, std::vector<float>* level_texels) const {
    for (size_t b = 0; b < global.size(); ++b)
      std::copy_n(x.data() + b * per_billboard * 4, per_billboard * 4,
                  level_texels->data() + global[b] * per_billboard * 4);
  }
};

// The photos view v's billboards of `level` are compared with: its own, then its neighbours'
// (the renderer blends the view's billboards near them too).
std::vector<FitImage> FitImages(const Volume& volume, int level, int v, const std::vector<View>& views,
                                const std::vector<ImageF>& photos, const BillboardFitOptions& options,
                                const ViewBillboards& billboards) {
  const bool finest = level + 1 == int(volume.levels.size());
  std::vector<int> seen_from = {v};
  for (int u : NeighbourViews(volume, v, options.neighbours)) seen_from.push_back(u);
  std::vector<FitImage> images;
  for (int u : seen_from) {
    // Neighbours constrain where along the view's rays the alpha sits, which half the resolution
    // shows as well: their photos are compared at twice the level's scale, a quarter of the work.
    const double scale = (u == v ? 1.0 : 2.0) * (finest ? 1.0 : std::max(1.0, TexelPixels(volume, level, views[u])));
    const View scaled = ScaledView(views[u], 1.0 / scale);
    FitImage image;
    image.target = AreaResample(photos[u], scaled.camera.width, scaled.camera.height);
    image.layers = RasterizeLevel(volume, level, scaled, ViewBlend{v, -1, 1, 0}, options.billboard_scale);
    image.weight = u == v ? 1.0f : float(options.neighbour_weight);
    image.scale = scale;
    billboards.Renumber(&image.layers);
    images.push_back(std::move(image));
  }
  return images;
}

// Projected, diagonally preconditioned Gauss-Newton from x; returns false when a value turned
// non-finite (x is then unspecified). A step is taken only when the objective falls and the own
// photo's error stays at most `own_limit`.
bool Minimise(const Objective& objective, int iterations, double own_limit, std::vector<float>* x,
              Objective::Value* value) {
  std::vector<float> gradient, diagonal, trial(x->size());
  *value = objective(*x, &gradient, &diagonal);
  double step = 1.0;
  for (int iteration = 0; iteration < iterations; ++iteration) {
    bool accepted = false;
    for (int attempt = 0; attempt < 6 && !accepted; ++attempt, step *= 0.5) {
      for (size_t i = 0; i < x->size(); ++i)
        trial[i] = diagonal[i] > 0 ? (*x)[i] - float(step) * gradient[i] / (2 * diagonal[i]) : (*x)[i];
      Project(&trial);
      const Objective::Value next = objective(trial);
      if (!std::isfinite(next.total)) return false;
      accepted = next.total < value->total && next.own <= own_limit;
    }
    if (!accepted) break;            // no descent left at any step length: converged
    step = std::min(1.0, step * 4);  // undo the last halving, and try a longer step next time
    x->swap(trial);
    *value = objective(*x, &gradient, &diagonal);
  }
  return true;
}

// Fits view v's billboards of one level; writes them into `texels` (the level's, as floats).
JobResult FitOneView(const Volume& volume, int level, int v, const std::vector<View>& views,
                     const std::vector<ImageF>& photos, const BillboardFitOptions& options,
                     std::vector<float>* texels) {
  const ViewBillboards billboards(volume, level, v);
  const std::vector<FitImage> images = FitImages(volume, level, v, views, photos, options, billboards);
  JobResult result;
  result.scale = images[0].scale;
  result.layers = images[0].layers.layers.size();
  result.pixels = size_t(images[0].target.width) * images[0].target.height;

  std::vector<float> x = billboards.Gather(*texels);
  const std::vector<float> start = x;
  const Objective objective{images, start, {1.0f, float(options.alpha_weight), float(options.prior)}};
  result.before = objective(x);
  // The renderer shows the own billboards alone at this input view: never worse there.
  if (!Minimise(objective, options.iterations, result.before.own, &x, &result.after)) {
    result.diverged = true;
    result.after = result.before;
    return result;
  }
  billboards.Scatter(x, texels);
  return result;
}

}  // namespace

void BillboardFitOptions::Check() const {
  if (iterations < 0) FailOption("BillboardFitOptions.iterations", "must be >= 0, got ", iterations);
  if (!(prior >= 0 && std::isfinite(prior))) FailOption("BillboardFitOptions.prior", "must be >= 0, got ", prior);
  if (!(alpha_weight > 0 && std::isfinite(alpha_weight)))
    FailOption("BillboardFitOptions.alpha_weight", "must be > 0, got ", alpha_weight);
  if (!(billboard_scale > 0)) FailOption("BillboardFitOptions.billboard_scale", "must be > 0, got ", billboard_scale);
  if (neighbours < 0) FailOption("BillboardFitOptions.neighbours", "must be >= 0, got ", neighbours);
  if (!(neighbour_weight >= 0 && std::isfinite(neighbour_weight)))
    FailOption("BillboardFitOptions.neighbour_weight", "must be >= 0, got ", neighbour_weight);
}

BillboardFitReport FitBillboards(const std::vector<View>& views, const std::vector<Image8>& mattes,
                                 const std::vector<Image8>& foreground, const BillboardFitOptions& options,
                                 Volume* volume, Progress* progress) {
  options.Check();
  const auto start = std::chrono::steady_clock::now();
  const int n_views = int(views.size()), n_levels = int(volume->levels.size());
  if (mattes.size() != views.size() || foreground.size() != views.size())
    Fail("fit: ", views.size(), " views but ", mattes.size(), " mattes and ", foreground.size(), " foregrounds");
  if (volume->views.size() != views.size())
    Fail("fit: the volume has ", volume->views.size(), " views, the photos ", views.size());
  std::vector<ImageF> photos(n_views);
  tbb::parallel_for(0, n_views, [&](int v) { photos[v] = PhotoTarget(mattes[v], foreground[v]); });
  std::vector<std::vector<float>> texels(n_levels);
  for (int l = 0; l < n_levels; ++l) texels[l] = TexelsAsFloat(volume->levels[l]);

  // Finest level first: it is the largest job, so the others fill in around it.
  std::vector<JobResult> results(size_t(n_levels) * n_views);
  std::atomic<size_t> done{0};
  tbb::parallel_for(
      size_t(0), results.size(),
      [&](size_t job) {
        const int level = n_levels - 1 - int(job / n_views), v = int(job % n_views);
        results[job] = FitOneView(*volume, level, v, views, photos, options, &texels[level]);
        if (progress) progress->Step("fit", ++done, results.size());
      },
      tbb::simple_partitioner());

  BillboardFitReport report;
  for (int l = 0; l < n_levels; ++l) {
    BillboardFitLevel out;
    out.level = l;
    double pixels = 0, rgb_before = 0, rgb_after = 0, alpha_before = 0, alpha_after = 0;
    for (int v = 0; v < n_views; ++v) {
      const JobResult& r = results[size_t(n_levels - 1 - l) * n_views + v];
      if (r.diverged)
        report.warnings.push_back(Str("level ", l, ", view '", views[v].name,
                                      "': the fit diverged; "
                                      "its unfitted billboards are kept"));
      out.scale += r.scale / n_views;
      out.layers += r.layers;
      pixels += double(r.pixels);
      rgb_before += r.before.rgb_sse, rgb_after += r.after.rgb_sse;
      alpha_before += r.before.alpha_sse, alpha_after += r.after.alpha_sse;
      out.loss_before += r.before.total, out.loss_after += r.after.total;
    }
    out.rgb_psnr_before = Psnr(rgb_before, 3 * pixels), out.rgb_psnr_after = Psnr(rgb_after, 3 * pixels);
    out.alpha_psnr_before = Psnr(alpha_before, pixels), out.alpha_psnr_after = Psnr(alpha_after, pixels);
    VolumeLevel& level = volume->levels[l];
    for (size_t i = 0; i < level.texels.size(); ++i)
      level.texels[i] = uint8_t(std::lround(std::clamp(texels[l][i], 0.0f, 1.0f) * 255.0f));
    report.levels.push_back(out);
  }
  report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return report;
}

}  // namespace voltree
