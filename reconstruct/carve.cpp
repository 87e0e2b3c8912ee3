#include "reconstruct/carve.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace voltree {

bool ProjectBox(const View& view, const Eigen::Vector3d& lo, const Eigen::Vector3d& hi, double* min_x, double* min_y,
                double* max_x, double* max_y) {
  *min_x = *min_y = std::numeric_limits<double>::infinity();
  *max_x = *max_y = -std::numeric_limits<double>::infinity();
  for (int corner = 0; corner < 8; ++corner) {
    const Eigen::Vector3d p((corner & 1) ? hi.x() : lo.x(), (corner & 2) ? hi.y() : lo.y(),
                            (corner & 4) ? hi.z() : lo.z());
    Eigen::Vector2d pixel;
    if (!view.WorldToPixel(p, &pixel)) return false;
    *min_x = std::min(*min_x, pixel.x());
    *min_y = std::min(*min_y, pixel.y());
    *max_x = std::max(*max_x, pixel.x());
    *max_y = std::max(*max_y, pixel.y());
  }
  return true;
}

std::vector<CellCoord> CarveCells(const GridFrame& frame, int level, const std::vector<CellCoord>& candidates,
                                  const std::vector<View>& views, const std::vector<MatteStats>& mattes,
                                  int empty_views) {
  const double size = frame.CellSize(level);
  std::vector<uint8_t> keep(candidates.size(), 1);
  tbb::parallel_for(size_t(0), candidates.size(), [&](size_t i) {
    const Eigen::Vector3d lo = frame.CellMin(level, candidates[i]);
    const Eigen::Vector3d hi = lo + Eigen::Vector3d::Constant(size);
    int empty = 0;
    for (size_t v = 0; v < views.size(); ++v) {
      double x0, y0, x1, y1;
      if (!ProjectBox(views[v], lo, hi, &x0, &y0, &x1, &y1)) continue;
      const PixelBox box = CoveredPixels(x0, y0, x1, y1);
      const MatteStats& m = mattes[v];
      if (box.x0 < 0 || box.y0 < 0 || box.x1 > m.width() || box.y1 > m.height()) continue;
      if (m.Occupied(box) == 0 && ++empty >= empty_views) {
        keep[i] = 0;
        return;
      }
    }
  });
  std::vector<CellCoord> kept;
  for (size_t i = 0; i < candidates.size(); ++i)
    if (keep[i]) kept.push_back(candidates[i]);
  return kept;
}

}  // namespace voltree
