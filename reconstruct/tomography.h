// The linear system of one level: every sampled pixel ray gives sum_c l_c sigma_c = b with
// b = -ln(max(1 - alpha, eps)), alpha averaged as transmittance over the ray's footprint.
// Rays are sampled on a regular block grid per view at about half the projected cell size.
// The (cell, length) entries are stored when they fit in `max_stored_bytes`, otherwise every
// pass walks the rays again with the DDA (streamed); both give bit-identical numbers.
#pragma once

#include <cstdint>
#include <vector>

#include "core/camera.h"
#include "reconstruct/dda.h"
#include "reconstruct/grid.h"
#include "reconstruct/matte_stats.h"
#include "reconstruct/optical_depth.h"

namespace voltree {

struct TomographyOptions {
  double epsilon = kDefaultAlphaEpsilon;      // of the optical depth (optical_depth.h)
  double samples_per_cell = 2;                // rays per projected cell edge
  size_t max_stored_bytes = size_t(1) << 30;  // larger ray systems are streamed

  void Check() const;  // throws OptionError naming the field
};

// One view's sampled rays at a level.
struct ViewRays {
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();  // camera centre
  std::vector<Eigen::Vector3d> directions;
  std::vector<float> b;
  // Stored entries (CSR), empty when streamed.
  std::vector<uint64_t> offsets;
  std::vector<uint32_t> cells;
  std::vector<float> lengths;
};

// Contiguous view ranges, fixed by the view count only, so that per-chunk reductions summed in
// chunk order give the same bits for any number of threads.
std::vector<std::pair<size_t, size_t>> ViewChunks(size_t views);

class TomographySystem {
 public:
  TomographySystem(const GridFrame& frame, int level, const LevelCells& cells, const std::vector<View>& views,
                   const std::vector<MatteStats>& mattes, const TomographyOptions& options);

  size_t cell_count() const { return cells_.size(); }
  size_t view_count() const { return rays_.size(); }
  size_t ray_count() const;
  size_t entry_count() const { return entries_; }
  bool stored() const { return stored_; }
  const std::vector<double>& column_sums() const { return column_sums_; }

  // Calls f(cells, lengths, count, b) for every ray of `view` that crosses a kept cell, in a
  // fixed order. Thread-safe; `scratch` buffers are the caller's (one per thread).
  template <typename F>
  void ForEachRay(size_t view, std::vector<uint32_t>* scratch_cells, std::vector<float>* scratch_lengths, F&& f) const;

 private:
  void Walk(const Ray& ray, std::vector<uint32_t>* cells, std::vector<float>* lengths) const;

  const LevelCells& cells_;
  GridWindow window_;
  std::vector<ViewRays> rays_;
  std::vector<double> column_sums_;
  size_t entries_ = 0;
  bool stored_ = false;
};

template <typename F>
void TomographySystem::ForEachRay(size_t view, std::vector<uint32_t>* scratch_cells,
                                  std::vector<float>* scratch_lengths, F&& f) const {
  const ViewRays& vr = rays_[view];
  for (size_t r = 0; r < vr.directions.size(); ++r) {
    if (stored_) {
      const uint64_t begin = vr.offsets[r], end = vr.offsets[r + 1];
      if (end > begin) f(vr.cells.data() + begin, vr.lengths.data() + begin, size_t(end - begin), vr.b[r]);
    } else {
      Walk(Ray{vr.origin, vr.directions[r]}, scratch_cells, scratch_lengths);
      if (!scratch_cells->empty()) f(scratch_cells->data(), scratch_lengths->data(), scratch_cells->size(), vr.b[r]);
    }
  }
}

}  // namespace voltree
