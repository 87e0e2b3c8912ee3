#include "reconstruct/billboard_raster.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/error.h"
#include "reconstruct/volume_order.h"

namespace voltree {
namespace {

// Billboard index of (cell, view) for every cell of a level, or -1 where the view was pruned.
std::vector<int32_t> BillboardOfCell(const VolumeLevel& level, int view) {
  std::vector<int32_t> out(level.cells.size(), -1);
  for (size_t b = 0; b < level.billboards.size(); ++b)
    if (level.billboards[b].view == view) out[level.billboards[b].cell] = int32_t(b);
  return out;
}

struct PlaneFrame {
  Eigen::Vector3d direction, right, up;
};

PlaneFrame FrameOf(const VolumeView& view) {
  const Eigen::Vector3d d = view.direction.normalized(), up = view.up.normalized();
  return {d, d.cross(up).normalized(), up};
}

// The bilinear tap the renderer's sampler takes at texture coordinates st in [0, 1]^2.
BillboardTap Tap(uint32_t billboard, int n, double s, double t, float weight) {
  auto axis = [n](double u, int* i0) {
    const double p = std::clamp(u * n, 0.5, n - 0.5) - 0.5;  // in [0, n - 1]
    *i0 = std::min(int(p), std::max(n - 2, 0));
    return float(p - *i0);
  };
  int col = 0, row = 0;
  BillboardTap tap;
  tap.fx = axis(s, &col);
  tap.fy = axis(t, &row);
  tap.texel = uint32_t((size_t(billboard) * n + row) * n + col);
  tap.weight = weight;
  return tap;
}

// Pixel rectangle [x0, x1) x [y0, y1) whose centres may see the squares; the whole image when a
// corner is behind the camera.
void SquareBounds(const View& camera, const Eigen::Vector3d& centre, double side, const PlaneFrame* frames, int count,
                  int* x0, int* y0, int* x1, int* y1) {
  double min_x = std::numeric_limits<double>::infinity(), min_y = min_x, max_x = -min_x, max_y = -min_x;
  for (int k = 0; k < count; ++k)
    for (int corner = 0; corner < 4; ++corner) {
      const Eigen::Vector3d p =
          centre +
          0.5 * side * ((corner & 1 ? 1.0 : -1.0) * frames[k].right + (corner & 2 ? 1.0 : -1.0) * frames[k].up);
      Eigen::Vector2d pixel;
      if (camera.pose.ToCamera(p).z() <= 0 || !camera.WorldToPixel(p, &pixel)) {
        *x0 = *y0 = 0, *x1 = camera.camera.width, *y1 = camera.camera.height;
        return;
      }
      min_x = std::min(min_x, pixel.x()), max_x = std::max(max_x, pixel.x());
      min_y = std::min(min_y, pixel.y()), max_y = std::max(max_y, pixel.y());
    }
  // One pixel of slack for lens distortion between the corners.
  *x0 = std::max(0, int(std::floor(min_x - 1))), *x1 = std::min(camera.camera.width, int(std::ceil(max_x + 1)));
  *y0 = std::max(0, int(std::floor(min_y - 1))), *y1 = std::min(camera.camera.height, int(std::ceil(max_y + 1)));
}

}  // namespace

LayerImage RasterizeLevel(const Volume& volume, int level, const View& camera, const ViewBlend& blend,
                          double billboard_scale) {
  const int width = camera.camera.width, height = camera.camera.height, n = volume.texels;
  const int count = blend.second >= 0 && blend.second != blend.first && blend.second_weight > 0 ? 2 : 1;
  const int views[2] = {blend.first, blend.second};
  const float weights[2] = {count == 2 ? blend.first_weight : 1.0f, blend.second_weight};
  for (int k = 0; k < count; ++k)
    if (views[k] < 0 || views[k] >= int(volume.views.size()))
      Fail("raster: view ", views[k], " is outside the volume's ", volume.views.size(), " views");
  const VolumeLevel& cells = volume.levels.at(level);
  std::vector<int32_t> billboard[2];
  PlaneFrame frames[2];
  for (int k = 0; k < count; ++k) {
    billboard[k] = BillboardOfCell(cells, views[k]);
    frames[k] = FrameOf(volume.views[views[k]]);
  }
  const Eigen::Vector3d eye = camera.pose.Center();
  std::vector<Eigen::Vector3f> rays(size_t(width) * height);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x)
      rays[size_t(y) * width + x] = camera.PixelRay(Eigen::Vector2d(x + 0.5, y + 0.5)).cast<float>();

  // Layers in drawing order with their pixels, then grouped by pixel (stable: order kept).
  std::vector<uint32_t> pixel_of;
  std::vector<BillboardLayer> drawn;
  const double side = billboard_scale * volume.CellSize(level);
  for (uint32_t cell : BackToFrontCells(volume, level, eye)) {
    const int32_t ids[2] = {billboard[0][cell], count == 2 ? billboard[1][cell] : -1};
    if (ids[0] < 0 && ids[1] < 0) continue;
    const Eigen::Vector3d centre = volume.CellCenter(level, cells.cells[cell]);
    int x0, y0, x1, y1;
    SquareBounds(camera, centre, side, frames, count, &x0, &y0, &x1, &y1);
    for (int y = y0; y < y1; ++y)
      for (int x = x0; x < x1; ++x) {
        const Eigen::Vector3d ray = rays[size_t(y) * width + x].cast<double>();
        BillboardLayer layer;
        bool any = false;
        for (int k = 0; k < count; ++k) {
          if (ids[k] < 0) continue;
          const double denominator = ray.dot(frames[k].direction);
          if (std::abs(denominator) < 1e-12) continue;
          const Eigen::Vector3d local = eye + ray * ((centre - eye).dot(frames[k].direction) / denominator) - centre;
          const double s = local.dot(frames[k].right) / side + 0.5, t = -local.dot(frames[k].up) / side + 0.5;
          if (s < 0 || s > 1 || t < 0 || t > 1) continue;
          layer.taps[k] = Tap(uint32_t(ids[k]), n, s, t, weights[k]);
          any = true;
        }
        if (!any) continue;
        pixel_of.push_back(uint32_t(size_t(y) * width + x));
        drawn.push_back(layer);
      }
  }
  LayerImage out;
  out.width = width, out.height = height, out.texels = n;
  out.offsets.assign(size_t(width) * height + 1, 0);
  for (uint32_t p : pixel_of) ++out.offsets[p + 1];
  for (size_t p = 0; p + 1 < out.offsets.size(); ++p) out.offsets[p + 1] += out.offsets[p];
  out.layers.resize(drawn.size());
  std::vector<uint32_t> fill(out.offsets.begin(), out.offsets.end() - 1);
  for (size_t i = 0; i < drawn.size(); ++i) out.layers[fill[pixel_of[i]]++] = drawn[i];
  return out;
}

namespace {

template <typename Texel>
ImageF Composite(const LayerImage& image, const Texel* texels, float scale) {
  ImageF out(image.width, image.height, 4);
  for (size_t p = 0; p + 1 < image.offsets.size(); ++p) {
    std::array<float, 4> colour{0, 0, 0, 0};
    for (uint32_t i = image.offsets[p]; i < image.offsets[p + 1]; ++i) {
      const std::array<float, 4> s = SampleLayer(image.layers[i], texels, image.texels, scale);
      for (int c = 0; c < 4; ++c) colour[c] = s[c] + (1 - s[3]) * colour[c];
    }
    std::copy(colour.begin(), colour.end(), out.pixels.begin() + p * 4);
  }
  return out;
}

}  // namespace

ImageF CompositeLayers(const LayerImage& image, const std::vector<float>& texels) {
  return Composite(image, texels.data(), 1.0f);
}

ImageF CompositeLayers(const LayerImage& image, const std::vector<uint8_t>& texels) {
  return Composite(image, texels.data(), 1.0f / 255.0f);
}

std::vector<float> TexelsAsFloat(const VolumeLevel& level) {
  std::vector<float> out(level.texels.size());
  for (size_t i = 0; i < out.size(); ++i) out[i] = level.texels[i] / 255.0f;
  return out;
}

}  // namespace voltree
