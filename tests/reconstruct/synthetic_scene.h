// Small synthetic inputs for the reconstruct tests: rings of cameras around the unit cube and a
// density phantom on a regular grid, imaged with the same forward model as the reconstruction
// (DDA line integrals, alpha = 1 - exp(-optical depth), 8-bit mattes).
#pragma once

#include <cmath>
#include <vector>

#include "core/camera.h"
#include "core/image.h"
#include "reconstruct/dda.h"
#include "reconstruct/grid.h"
#include "reconstruct/reconstruct.h"

namespace voltree::testing {

// `count` cameras on two rings (elevations +-25 degrees, alternating) at distance 3 around the
// centre of [0,1]^3, looking at it, +Z up; the cube fills about 80 % of a size x size image.
inline std::vector<View> RingViews(int count, int size) {
  std::vector<View> views;
  const Eigen::Vector3d centre(0.5, 0.5, 0.5);
  for (int i = 0; i < count; ++i) {
    const double azimuth = 2 * M_PI * i / count;
    const double elevation = (i % 2 ? 25.0 : -25.0) * M_PI / 180;
    const Eigen::Vector3d eye =
        centre + 3.0 * Eigen::Vector3d(std::cos(azimuth) * std::cos(elevation), std::sin(azimuth) * std::cos(elevation),
                                       std::sin(elevation));
    View view;
    view.name = "view_" + std::to_string(1000 + i).substr(1) + ".png";
    const double focal = 1.45 * size;
    view.camera = Camera::Pinhole(size, size, focal, focal, 0.5 * size, 0.5 * size);
    view.pose = Pose::LookAt(eye, centre, Eigen::Vector3d::UnitZ());
    views.push_back(view);
  }
  return views;
}

// Piecewise-constant density on a res^3 grid over [0,1]^3.
struct Phantom {
  int res = 16;
  std::vector<double> sigma;  // (z * res + y) * res + x
  double& at(int x, int y, int z) { return sigma[(size_t(z) * res + y) * res + x]; }
  double at(int x, int y, int z) const { return sigma[(size_t(z) * res + y) * res + x]; }
};

// Two Gaussian blobs and a box, all inside [0.15, 0.85]^3, peak sigma ~ 4 * scale per unit length.
inline Phantom BlobPhantom(int res, double scale = 1) {
  Phantom p{res, std::vector<double>(size_t(res) * res * res, 0.0)};
  for (int z = 0; z < res; ++z)
    for (int y = 0; y < res; ++y)
      for (int x = 0; x < res; ++x) {
        const Eigen::Vector3d c((x + 0.5) / res, (y + 0.5) / res, (z + 0.5) / res);
        double s = 4.0 * std::exp(-(c - Eigen::Vector3d(0.38, 0.42, 0.55)).squaredNorm() / (2 * 0.09 * 0.09)) +
                   3.0 * std::exp(-(c - Eigen::Vector3d(0.64, 0.6, 0.4)).squaredNorm() / (2 * 0.07 * 0.07));
        if (c.x() > 0.55 && c.x() < 0.75 && c.y() > 0.25 && c.y() < 0.4 && c.z() > 0.6 && c.z() < 0.8) s += 2.0;
        p.at(x, y, z) = s < 0.05 ? 0.0 : scale * s;
      }
  return p;
}

inline double OpticalDepth(const Phantom& p, const Ray& ray) {
  const GridWindow window{Eigen::Vector3d::Zero(), 1.0 / p.res, {0, 0, 0}, {p.res, p.res, p.res}};
  double depth = 0;
  TraverseGrid(window, ray, 0.0, 1e30, [&](int x, int y, int z, double length, double) {
    depth += p.at(x, y, z) * length;
    return true;
  });
  return depth;
}

// 8-bit matte of the phantom seen from `view`, `supersample`^2 rays per pixel averaged as
// transmittance.
inline Image8 PhantomMatte(const Phantom& p, const View& view, int supersample = 2) {
  Image8 matte(view.camera.width, view.camera.height, 1);
  for (int y = 0; y < matte.height; ++y)
    for (int x = 0; x < matte.width; ++x) {
      double transmittance = 0;
      for (int sy = 0; sy < supersample; ++sy)
        for (int sx = 0; sx < supersample; ++sx) {
          const Eigen::Vector2d pixel(x + (sx + 0.5) / supersample, y + (sy + 0.5) / supersample);
          transmittance += std::exp(-OpticalDepth(p, Ray{view.pose.Center(), view.PixelRay(pixel)}));
        }
      const double alpha = 1 - transmittance / (supersample * supersample);
      matte.at(x, y) = uint8_t(std::lround(255 * alpha));
    }
  return matte;
}

// Premultiplied RGBA: a colour that varies across the image, times the matte.
inline Image8 PhantomForeground(const Image8& matte) {
  Image8 rgba(matte.width, matte.height, 4);
  for (int y = 0; y < matte.height; ++y)
    for (int x = 0; x < matte.width; ++x) {
      const double a = matte.at(x, y) / 255.0;
      const double rgb[3] = {40 + 150.0 * x / matte.width, 120 + 100.0 * y / matte.height, 60};
      for (int c = 0; c < 3; ++c) rgba.at(x, y, c) = uint8_t(std::lround(rgb[c] * a));
      rgba.at(x, y, 3) = matte.at(x, y);
    }
  return rgba;
}

inline ReconstructInput PhantomInput(const Phantom& p, int views, int size) {
  ReconstructInput input;
  input.views = RingViews(views, size);
  for (const View& v : input.views) {
    input.mattes.push_back(PhantomMatte(p, v));
    input.foreground.push_back(PhantomForeground(input.mattes.back()));
  }
  input.bounds_min = Eigen::Vector3d::Zero();
  input.bounds_max = Eigen::Vector3d::Ones();
  input.source = "phantom";
  return input;
}

// Every cell of a resolution^3 grid, sorted by CellLess (z, then y, then x).
inline std::vector<CellCoord> EveryCell(int resolution) {
  std::vector<CellCoord> all;
  for (int z = 0; z < resolution; ++z)
    for (int y = 0; y < resolution; ++y)
      for (int x = 0; x < resolution; ++x) all.push_back({uint16_t(x), uint16_t(y), uint16_t(z)});
  return all;
}

}  // namespace voltree::testing

#include <algorithm>

#include "reconstruct/billboards.h"
#include "reconstruct/grid.h"
#include "temp_dir.h"

namespace voltree::testing {

// Alpha of one level of the volume's densities along a ray: 1 - exp(-sum sigma l).
inline double LevelAlong(const Volume& volume, int level, const Ray& ray) {
  const VolumeLevel& l = volume.levels[level];
  const LevelCells cells(l.resolution, l.cells);
  const GridWindow window{volume.origin, volume.CellSize(level), cells.box_min(), cells.box_max()};
  double depth = 0;
  TraverseGrid(window, ray, 0.0, 1e30, [&](int x, int y, int z, double length, double) {
    const int32_t j = cells.Find(x, y, z);
    if (j >= 0) depth += l.density[j] * length;
    return true;
  });
  return 1 - std::exp(-depth);
}

// The alpha (0..1) of billboard (cell, view) where `ray` meets its plane, or -1 when the ray
// misses the square or the billboard was pruned away.
inline double BillboardAlphaOnRay(const Volume& volume, int level, uint32_t cell, uint16_t view, const Ray& ray) {
  const VolumeLevel& l = volume.levels[level];
  const auto it = std::lower_bound(l.billboards.begin(), l.billboards.end(), std::pair{cell, view},
                                   [](const Billboard& b, const std::pair<uint32_t, uint16_t>& key) {
                                     return std::pair{b.cell, b.view} < key;
                                   });
  if (it == l.billboards.end() || it->cell != cell || it->view != view) return -1;
  const VolumeView& v = volume.views[view];
  const Eigen::Vector3d centre = volume.CellCenter(level, l.cells[cell]);
  const double t = (centre - ray.origin).dot(v.direction) / ray.direction.dot(v.direction);
  const Eigen::Vector3d hit = ray.origin + t * ray.direction - centre;
  const Eigen::Vector3d right = v.direction.cross(v.up);
  const double side = volume.CellSize(level);
  const int n = volume.texels;
  const int col = int(std::floor((hit.dot(right) / side + 0.5) * n));
  const int row = int(std::floor((0.5 - hit.dot(v.up) / side) * n));
  if (col < 0 || col >= n || row < 0 || row >= n) return -1;
  const size_t index = size_t(it - l.billboards.begin());
  return l.texels[(index * n * n + size_t(row) * n + col) * 4 + 3] / 255.0;
}

// Composites view `view`'s billboards of one level front to back along `ray` (the over operator
// on alpha); stops before `stop_cell` when given. Returns the accumulated alpha.
inline double CompositeBillboards(const Volume& volume, int level, uint16_t view, const Ray& ray,
                                  int64_t stop_cell = -1) {
  const VolumeLevel& l = volume.levels[level];
  const LevelCells cells(l.resolution, l.cells);
  const GridWindow window{volume.origin, volume.CellSize(level), cells.box_min(), cells.box_max()};
  double transmittance = 1;
  TraverseGrid(window, ray, 0.0, 1e30, [&](int x, int y, int z, double, double) {
    const int32_t j = cells.Find(x, y, z);
    if (j < 0) return true;
    if (j == stop_cell) return false;
    const double a = BillboardAlphaOnRay(volume, level, uint32_t(j), view, ray);
    if (a > 0) transmittance *= 1 - a;
    return true;
  });
  return 1 - transmittance;
}

}  // namespace voltree::testing
