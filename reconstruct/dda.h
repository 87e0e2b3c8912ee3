// 3D DDA (Amanatides & Woo 1987): the cells a ray crosses in a regular grid, in order, with the
// length of the ray inside each. The tomography and the billboards both walk rays with it.
#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace voltree {

struct Ray {
  Eigen::Vector3d origin;
  Eigen::Vector3d direction;  // unit length, so parameters are distances
};

// Ray parameters where the ray enters and leaves the box [lo, hi]; false when it misses the box
// or the overlap with [t_min, t_max] is empty.
inline bool ClipRayToBox(const Ray& ray, const Eigen::Vector3d& lo, const Eigen::Vector3d& hi, double t_min,
                         double t_max, double* t_enter, double* t_leave) {
  double t0 = t_min, t1 = t_max;
  for (int a = 0; a < 3; ++a) {
    const double d = ray.direction[a];
    if (d == 0) {
      if (ray.origin[a] < lo[a] || ray.origin[a] > hi[a]) return false;
      continue;
    }
    double ta = (lo[a] - ray.origin[a]) / d, tb = (hi[a] - ray.origin[a]) / d;
    if (ta > tb) std::swap(ta, tb);
    t0 = std::max(t0, ta);
    t1 = std::min(t1, tb);
  }
  *t_enter = t0;
  *t_leave = t1;
  return t0 < t1;
}

// A regular grid: `resolution` cells of edge `cell_size` per axis from `origin`. Traversal is
// limited to the cells [box_min, box_max) (e.g. the kept cells' bounds).
struct GridWindow {
  Eigen::Vector3d origin;
  double cell_size;
  std::array<int, 3> box_min;
  std::array<int, 3> box_max;
};

// Calls visit(x, y, z, length, t_enter) for every cell of the window the ray crosses within
// [t_min, t_max], front to back; stops early when visit returns false.
template <typename Visit>
void TraverseGrid(const GridWindow& grid, const Ray& ray, double t_min, double t_max, Visit&& visit) {
  for (int a = 0; a < 3; ++a)
    if (grid.box_min[a] >= grid.box_max[a]) return;  // no cells
  Eigen::Vector3d lo, hi;
  for (int a = 0; a < 3; ++a) {
    lo[a] = grid.origin[a] + grid.box_min[a] * grid.cell_size;
    hi[a] = grid.origin[a] + grid.box_max[a] * grid.cell_size;
  }
  double t, t_end;
  if (!ClipRayToBox(ray, lo, hi, t_min, t_max, &t, &t_end)) return;
  std::array<int, 3> cell, step;
  std::array<double, 3> t_next, t_delta;
  const Eigen::Vector3d start = ray.origin + ray.direction * (0.5 * (t + std::min(t_end, t + 1e-9 * grid.cell_size)));
  for (int a = 0; a < 3; ++a) {
    const int c = int(std::floor((start[a] - grid.origin[a]) / grid.cell_size));
    cell[a] = std::clamp(c, grid.box_min[a], grid.box_max[a] - 1);
    const double d = ray.direction[a];
    if (d > 0) {
      step[a] = 1;
      t_next[a] = (grid.origin[a] + (cell[a] + 1) * grid.cell_size - ray.origin[a]) / d;
      t_delta[a] = grid.cell_size / d;
    } else if (d < 0) {
      step[a] = -1;
      t_next[a] = (grid.origin[a] + cell[a] * grid.cell_size - ray.origin[a]) / d;
      t_delta[a] = -grid.cell_size / d;
    } else {
      step[a] = 0;
      t_next[a] = std::numeric_limits<double>::infinity();
      t_delta[a] = std::numeric_limits<double>::infinity();
    }
  }
  while (t < t_end) {
    const int a = (t_next[0] < t_next[1]) ? (t_next[0] < t_next[2] ? 0 : 2) : (t_next[1] < t_next[2] ? 1 : 2);
    const double t_exit = std::min(t_next[a], t_end);
    if (t_exit > t && !visit(cell[0], cell[1], cell[2], t_exit - t, t)) return;
    t = t_exit;
    cell[a] += step[a];
    if (cell[a] < grid.box_min[a] || cell[a] >= grid.box_max[a]) return;
    t_next[a] += t_delta[a];
  }
}

}  // namespace voltree
