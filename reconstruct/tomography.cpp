#include "reconstruct/tomography.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <cmath>

#include "core/error.h"

namespace voltree {

std::vector<std::pair<size_t, size_t>> ViewChunks(size_t views) {
  const size_t chunks = std::min<size_t>(views, 16);
  std::vector<std::pair<size_t, size_t>> out;
  for (size_t k = 0; k < chunks; ++k) out.emplace_back(k * views / chunks, (k + 1) * views / chunks);
  return out;
}

namespace {

// Block size in pixels so that a cell edge spans about `samples_per_cell` blocks, measured at the
// distance of the root cube's centre.
int BlockSize(const View& view, const GridFrame& frame, int level, double samples_per_cell) {
  const Eigen::Vector3d centre = frame.origin + Eigen::Vector3d::Constant(0.5 * frame.size);
  const double depth = std::max(view.pose.ToCamera(centre).z(), 1e-9);
  const double focal = 0.5 * (view.camera.FocalX() + view.camera.FocalY());
  const double cell_pixels = focal * frame.CellSize(level) / depth;
  return std::max(1, int(std::floor(cell_pixels / samples_per_cell)));
}

ViewRays SampleRays(const View& view, const MatteStats& matte, int block, double epsilon) {
  ViewRays rays;
  rays.origin = view.pose.Center();
  const int w = matte.width(), h = matte.height();
  for (int y0 = 0; y0 < h; y0 += block)
    for (int x0 = 0; x0 < w; x0 += block) {
      const PixelBox box{x0, y0, std::min(x0 + block, w), std::min(y0 + block, h)};
      const double alpha = matte.MeanAlpha(box);
      const Eigen::Vector2d centre(0.5 * (box.x0 + box.x1), 0.5 * (box.y0 + box.y1));
      rays.directions.push_back(view.PixelRay(centre));
      rays.b.push_back(float(OpticalDepth(alpha, epsilon)));
    }
  return rays;
}

}  // namespace

TomographySystem::TomographySystem(const GridFrame& frame, int level, const LevelCells& cells,
                                   const std::vector<View>& views, const std::vector<MatteStats>& mattes,
                                   const TomographyOptions& options)
    : cells_(cells) {
  window_ = GridWindow{frame.origin, frame.CellSize(level), cells.box_min(), cells.box_max()};
  rays_.resize(views.size());
  tbb::parallel_for(size_t(0), views.size(), [&](size_t v) {
    rays_[v] =
        SampleRays(views[v], mattes[v], BlockSize(views[v], frame, level, options.samples_per_cell), options.epsilon);
  });

  // Try to store the entries; give up (and stream) as soon as they exceed the budget.
  std::atomic<size_t> total_bytes{0};
  std::atomic<bool> over_budget{false};
  constexpr size_t kEntryBytes = sizeof(uint32_t) + sizeof(float);
  tbb::parallel_for(size_t(0), views.size(), [&](size_t v) {
    ViewRays& vr = rays_[v];
    std::vector<uint32_t> ray_cells;
    std::vector<float> ray_lengths;
    vr.offsets.assign(1, 0);
    for (const Eigen::Vector3d& direction : vr.directions) {
      if (over_budget.load(std::memory_order_relaxed)) return;
      Walk(Ray{vr.origin, direction}, &ray_cells, &ray_lengths);
      vr.cells.insert(vr.cells.end(), ray_cells.begin(), ray_cells.end());
      vr.lengths.insert(vr.lengths.end(), ray_lengths.begin(), ray_lengths.end());
      vr.offsets.push_back(vr.cells.size());
      if (total_bytes.fetch_add(ray_cells.size() * kEntryBytes) + ray_cells.size() * kEntryBytes >
          options.max_stored_bytes)
        over_budget = true;
    }
  });
  stored_ = !over_budget;
  if (!stored_)
    for (ViewRays& vr : rays_) {
      vr.offsets = {};
      vr.cells = {};
      vr.lengths = {};
    }

  // Column sums, chunked and reduced in chunk order.
  const auto chunks = ViewChunks(views.size());
  std::vector<std::vector<double>> partial(chunks.size(), std::vector<double>(cells.size(), 0.0));
  std::vector<size_t> partial_entries(chunks.size(), 0);
  tbb::parallel_for(size_t(0), chunks.size(), [&](size_t k) {
    std::vector<uint32_t> sc;
    std::vector<float> sl;
    for (size_t v = chunks[k].first; v < chunks[k].second; ++v)
      ForEachRay(v, &sc, &sl, [&](const uint32_t* c, const float* l, size_t n, float) {
        for (size_t i = 0; i < n; ++i) partial[k][c[i]] += l[i];
        partial_entries[k] += n;
      });
  });
  column_sums_.assign(cells.size(), 0.0);
  for (size_t k = 0; k < chunks.size(); ++k) {
    for (size_t c = 0; c < cells.size(); ++c) column_sums_[c] += partial[k][c];
    entries_ += partial_entries[k];
  }
}

size_t TomographySystem::ray_count() const {
  size_t n = 0;
  for (const ViewRays& vr : rays_) n += vr.directions.size();
  return n;
}

void TomographySystem::Walk(const Ray& ray, std::vector<uint32_t>* cells, std::vector<float>* lengths) const {
  cells->clear();
  lengths->clear();
  TraverseGrid(window_, ray, 0.0, std::numeric_limits<double>::infinity(),
               [&](int x, int y, int z, double length, double) {
                 const int32_t index = cells_.Find(x, y, z);
                 if (index >= 0) {
                   cells->push_back(uint32_t(index));
                   lengths->push_back(float(length));
                 }
                 return true;
               });
}

void TomographyOptions::Check() const {
  if (!(epsilon > 0 && epsilon < 1)) FailOption("TomographyOptions.epsilon", "must be in (0, 1), got ", epsilon);
  if (!(samples_per_cell > 0))
    FailOption("TomographyOptions.samples_per_cell", "must be positive, got ", samples_per_cell);
}

}  // namespace voltree
