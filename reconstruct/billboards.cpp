#include "reconstruct/billboards.h"

#include <tbb/parallel_for.h>

#include <cmath>
#include <limits>

#include "core/error.h"
#include "reconstruct/dda.h"
#include "reconstruct/grid.h"

namespace voltree {

VolumeView MakeVolumeView(const View& view) {
  VolumeView out;
  out.name = view.name;
  out.position = view.pose.Center();
  out.direction = view.pose.ViewDirection();
  out.up = view.pose.rotation.conjugate() * Eigen::Vector3d(0, -1, 0);
  return out;
}

Eigen::Vector3d TexelCenter(const VolumeView& view, const Eigen::Vector3d& centre, double side, int texels, int row,
                            int col) {
  const Eigen::Vector3d right = view.direction.cross(view.up);  // image +X = Z x (-Y)
  const double u = ((col + 0.5) / texels - 0.5) * side;
  const double v = (0.5 - (row + 0.5) / texels) * side;
  return centre + u * right + v * view.up;
}

namespace {

struct LevelInput {
  GridFrame frame;
  int level = 0;
  LevelCells cells;
  const std::vector<float>* density = nullptr;
  GridWindow window;
};

// Texels of one (cell, view) billboard into `out` (n*n*4 bytes); returns whether any alpha > 1/255.
bool MakeBillboard(const LevelInput& in, size_t cell, const View& view, const VolumeView& frame_view,
                   const MatteStats& matte, const ColourStats& colour, int texels, const BillboardOptions& options,
                   uint8_t* out) {
  const Eigen::Vector3d centre = in.frame.CellCenter(in.level, in.cells.cell(cell));
  const double side = options.scale * in.frame.CellSize(in.level);
  const double focal = 0.5 * (view.camera.FocalX() + view.camera.FocalY());
  const std::vector<float>& sigma = *in.density;
  bool visible = false;
  for (int row = 0; row < texels; ++row)
    for (int col = 0; col < texels; ++col) {
      uint8_t* texel = out + (size_t(row) * texels + col) * 4;
      texel[0] = texel[1] = texel[2] = texel[3] = 0;
      const Eigen::Vector3d p = TexelCenter(frame_view, centre, side, texels, row, col);
      Eigen::Vector2d pixel;
      if (!view.WorldToPixel(p, &pixel)) continue;
      const double half = 0.5 * focal * (side / texels) / view.pose.ToCamera(p).z();
      const PixelBox box = CoveredPixels(pixel.x() - half, pixel.y() - half, pixel.x() + half, pixel.y() + half);
      const double alpha = matte.MeanAlpha(box);
      if (alpha <= 0) continue;  // outside the image or transparent there
      const double b = OpticalDepth(alpha, options.epsilon);
      double total = 0, front = 0, own = 0;
      bool reached = false;
      const Ray ray{frame_view.position, (p - frame_view.position).normalized()};
      TraverseGrid(in.window, ray, 0.0, std::numeric_limits<double>::infinity(),
                   [&](int x, int y, int z, double length, double) {
                     const int32_t j = in.cells.Find(x, y, z);
                     if (j < 0) return true;
                     const double depth = double(sigma[j]) * length;
                     total += depth;
                     if (size_t(j) == cell) {
                       own = depth;
                       reached = true;
                     } else if (!reached) {
                       front += depth;
                     }
                     return true;
                   });
      if (!reached || own <= 0 || total <= 0) continue;
      const double gamma = b / total;
      if (1.0 - std::exp(-gamma * front) > options.prune) continue;  // hidden behind the cells in front
      const double a = 1.0 - std::exp(-gamma * own);
      const auto straight = colour.MeanStraightColour(box);
      texel[3] = uint8_t(std::lround(255.0 * a));
      for (int c = 0; c < 3; ++c) texel[c] = uint8_t(std::lround(straight[c] * a));
      visible = visible || texel[3] > 1;
    }
  return visible;
}

}  // namespace

void MakeBillboards(const std::vector<View>& views, const std::vector<MatteStats>& mattes,
                    const std::vector<Image8>& foreground, const BillboardOptions& options, Volume* volume,
                    Progress* progress) {
  const int n = volume->texels;
  const size_t bytes = volume->BytesPerBillboard();
  const size_t n_views = views.size();
  GridFrame frame{volume->origin, volume->size, volume->branching};
  std::vector<LevelInput> inputs(volume->levels.size());
  std::vector<std::vector<uint8_t>> texels(volume->levels.size());
  std::vector<std::vector<uint8_t>> visible(volume->levels.size());
  for (size_t l = 0; l < volume->levels.size(); ++l) {
    const VolumeLevel& level = volume->levels[l];
    LevelInput& in = inputs[l];
    in.frame = frame;
    in.level = int(l);
    in.cells = LevelCells(level.resolution, level.cells);
    in.density = &level.density;
    in.window = GridWindow{frame.origin, frame.CellSize(int(l)), in.cells.box_min(), in.cells.box_max()};
    texels[l].assign(level.cells.size() * n_views * bytes, 0);
    visible[l].assign(level.cells.size() * n_views, 0);
  }
  volume->views.clear();
  for (const View& v : views) volume->views.push_back(MakeVolumeView(v));

  for (size_t v = 0; v < n_views; ++v) {
    const ColourStats colour(foreground[v]);
    for (size_t l = 0; l < inputs.size(); ++l) {
      const size_t n_cells = volume->levels[l].cells.size();
      tbb::parallel_for(size_t(0), n_cells, [&](size_t c) {
        const size_t slot = c * n_views + v;
        visible[l][slot] = MakeBillboard(inputs[l], c, views[v], volume->views[v], mattes[v], colour, n, options,
                                         texels[l].data() + slot * bytes);
      });
    }
    if (progress) progress->Say("billboards", Str("view ", v + 1, "/", n_views, " (", views[v].name, ")"));
  }

  for (size_t l = 0; l < inputs.size(); ++l) {
    VolumeLevel& level = volume->levels[l];
    level.billboards.clear();
    level.texels.clear();
    level.billboards_before_pruning = level.cells.size() * n_views;
    for (size_t slot = 0; slot < visible[l].size(); ++slot) {
      if (!visible[l][slot]) continue;
      level.billboards.push_back(Billboard{uint32_t(slot / n_views), uint16_t(slot % n_views)});
      level.texels.insert(level.texels.end(), texels[l].begin() + slot * bytes, texels[l].begin() + (slot + 1) * bytes);
    }
    std::vector<uint8_t>().swap(texels[l]);
  }
}

void BillboardOptions::Check() const {
  if (!(prune > 0 && prune <= 1)) FailOption("BillboardOptions.prune", "must be in (0, 1], got ", prune);
  if (!(scale > 0)) FailOption("BillboardOptions.scale", "must be positive, got ", scale);
  if (!(epsilon > 0 && epsilon < 1)) FailOption("BillboardOptions.epsilon", "must be in (0, 1), got ", epsilon);
}

}  // namespace voltree
