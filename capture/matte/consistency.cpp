#include "capture/matte/consistency.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>

#include "capture/normalize.h"
#include "core/error.h"

namespace voltree {
namespace {

// One photo at the comparison size: its tree mask, what it does not see as sure background
// dilated by a voxel's footprint (where it cannot carve), and the scale from camera pixels to
// mask pixels.
struct PhotoMasks {
  cv::Mat tree, dilated;
  Eigen::Vector2d scale;
};

PhotoMasks MakeMasks(const View& view, const Image8& matte, const MatteConsistencyOptions& options,
                     double voxel_radius_pixels) {
  if (matte.channels != 1) Fail(view.name, ": a matte must have one channel, got ", matte.channels);
  const cv::Mat alpha(matte.height, matte.width, CV_8UC1, const_cast<uint8_t*>(matte.pixels.data()));
  const double shrink = std::min(1.0, double(options.max_side) / std::max(view.camera.width, view.camera.height));
  const int width = std::max(1, int(std::lround(view.camera.width * shrink)));
  const int height = std::max(1, int(std::lround(view.camera.height * shrink)));
  cv::Mat small;
  cv::resize(alpha, small, cv::Size(width, height), 0, 0, cv::INTER_AREA);
  PhotoMasks masks;
  cv::threshold(small, masks.tree, options.matte_threshold * 255.0, 255, cv::THRESH_BINARY);
  cv::Mat not_background;
  cv::threshold(small, not_background, options.carve_threshold * 255.0, 255, cv::THRESH_BINARY);
  const int radius = int(std::ceil(voxel_radius_pixels * shrink)) + 1;
  cv::dilate(not_background, masks.dilated,
             cv::getStructuringElement(cv::MORPH_ELLIPSE, cv::Size(2 * radius + 1, 2 * radius + 1)));
  masks.scale = {double(width) / view.camera.width, double(height) / view.camera.height};
  return masks;
}

struct Grid {
  Eigen::Vector3d min;
  double voxel = 0;
  Eigen::Vector3i cells;
  Eigen::Vector3d Center(int x, int y, int z) const { return min + voxel * Eigen::Vector3d(x + 0.5, y + 0.5, z + 0.5); }
  size_t Index(int x, int y, int z) const { return (size_t(z) * cells.y() + y) * cells.x() + x; }
  size_t Size() const { return size_t(cells.x()) * cells.y() * cells.z(); }
};

// Whether a voxel centre projects inside view v's mask image; its pixel in `pixel`.
bool ProjectToMask(const View& view, const PhotoMasks& masks, const Eigen::Vector3d& point, cv::Point* pixel) {
  Eigen::Vector2d p;
  if (!view.WorldToPixel(point, &p) || view.pose.ToCamera(point).z() <= 0) return false;
  pixel->x = int(std::floor(p.x() * masks.scale.x()));
  pixel->y = int(std::floor(p.y() * masks.scale.y()));
  return pixel->x >= 0 && pixel->y >= 0 && pixel->x < masks.tree.cols && pixel->y < masks.tree.rows;
}

// Carves `grid` with outvoting: kept when seen by at least `min_seen` photos and at most
// `allowed` of them see it off their dilated matte.
std::vector<uint8_t> Carve(const Grid& grid, const std::vector<View>& views, const std::vector<PhotoMasks>& masks,
                           int min_seen, int allowed, double allowed_share) {
  std::vector<uint8_t> kept(grid.Size(), 0);
  tbb::parallel_for(tbb::blocked_range<int>(0, grid.cells.z()), [&](const tbb::blocked_range<int>& slices) {
    for (int z = slices.begin(); z < slices.end(); ++z)
      for (int y = 0; y < grid.cells.y(); ++y)
        for (int x = 0; x < grid.cells.x(); ++x) {
          const Eigen::Vector3d center = grid.Center(x, y, z);
          int seen = 0, carved = 0;
          for (size_t v = 0; v < views.size() && carved <= allowed; ++v) {
            cv::Point pixel;
            if (!ProjectToMask(views[v], masks[v], center, &pixel)) continue;
            ++seen;
            carved += masks[v].dilated.at<uint8_t>(pixel) == 0;
          }
          kept[grid.Index(x, y, z)] = carved <= allowed && carved <= allowed_share * seen && seen >= min_seen;
        }
  });
  return kept;
}

// The bounds (in voxels) of the kept voxels; false when none is kept.
bool KeptBounds(const Grid& grid, const std::vector<uint8_t>& kept, Eigen::Vector3i* low, Eigen::Vector3i* high) {
  *low = grid.cells;
  *high = Eigen::Vector3i::Constant(-1);
  for (int z = 0; z < grid.cells.z(); ++z)
    for (int y = 0; y < grid.cells.y(); ++y)
      for (int x = 0; x < grid.cells.x(); ++x)
        if (kept[grid.Index(x, y, z)]) {
          *low = low->cwiseMin(Eigen::Vector3i(x, y, z));
          *high = high->cwiseMax(Eigen::Vector3i(x, y, z));
        }
  return high->x() >= 0;
}

Grid MakeGrid(const Eigen::Vector3d& min, const Eigen::Vector3d& max, int resolution) {
  Grid grid;
  grid.min = min;
  grid.voxel = (max - min).maxCoeff() / resolution;
  grid.cells = ((max - min) / grid.voxel).array().ceil().cast<int>().max(1);
  return grid;
}

std::vector<PhotoMasks> MakeAllMasks(const std::vector<View>& views, const std::vector<Image8>& mattes,
                                     const MatteConsistencyOptions& options, const Grid& grid) {
  const Eigen::Vector3d center = grid.min + 0.5 * grid.voxel * grid.cells.cast<double>();
  std::vector<PhotoMasks> masks(views.size());
  tbb::parallel_for(size_t(0), views.size(), [&](size_t v) {
    const double depth = std::max(views[v].pose.ToCamera(center).z(), 1e-9);
    const double radius = views[v].camera.FocalX() * grid.voxel * 0.87 / depth;  // half-diagonal
    masks[v] = MakeMasks(views[v], mattes[v], options, radius);
  });
  return masks;
}

struct CarvedHull {
  Grid grid;
  std::vector<uint8_t> kept;
  std::vector<PhotoMasks> masks;
};

// Coarse: a cube around the point the cameras look at, as large as their mean distance; then
// the kept voxels' bounds plus a margin at the same resolution.
CarvedHull CarveTwice(const std::vector<View>& views, const std::vector<Image8>& mattes,
                      const MatteConsistencyOptions& options) {
  const int allowed = std::max(1, int(std::floor(options.outvoted_fraction * double(views.size()))));
  const int min_seen = std::max(2, int(std::ceil(options.min_seen_fraction * double(views.size()))));
  const Eigen::Vector3d target = LookAtPoint(views);
  double distance = 0;
  for (const View& view : views) distance += (view.pose.Center() - target).norm();
  distance /= double(views.size());
  CarvedHull hull;
  hull.grid = MakeGrid(target - Eigen::Vector3d::Constant(distance), target + Eigen::Vector3d::Constant(distance),
                       options.resolution);
  hull.masks = MakeAllMasks(views, mattes, options, hull.grid);
  hull.kept = Carve(hull.grid, views, hull.masks, min_seen, allowed, options.outvoted_share_of_seen);
  Eigen::Vector3i low, high;
  if (KeptBounds(hull.grid, hull.kept, &low, &high)) {
    const Eigen::Vector3d margin = Eigen::Vector3d::Constant(2 * hull.grid.voxel);
    hull.grid = MakeGrid(hull.grid.min + hull.grid.voxel * low.cast<double>() - margin,
                         hull.grid.min + hull.grid.voxel * (high + Eigen::Vector3i::Ones()).cast<double>() + margin,
                         options.resolution);
    hull.masks = MakeAllMasks(views, mattes, options, hull.grid);
    hull.kept = Carve(hull.grid, views, hull.masks, min_seen, allowed, options.outvoted_share_of_seen);
  }
  return hull;
}

// Whether a kept voxel has an empty face neighbour (only those shape the projection).
bool OnSurface(const Grid& grid, const std::vector<uint8_t>& kept, int x, int y, int z) {
  const int offsets[6][3] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  for (const auto& o : offsets) {
    const int nx = x + o[0], ny = y + o[1], nz = z + o[2];
    if (nx < 0 || ny < 0 || nz < 0 || nx >= grid.cells.x() || ny >= grid.cells.y() || nz >= grid.cells.z()) return true;
    if (!kept[grid.Index(nx, ny, nz)]) return true;
  }
  return false;
}

// The 6-connected parts of the kept voxels, largest first.
std::vector<HullPart> ConnectedParts(const Grid& grid, const std::vector<uint8_t>& kept) {
  std::vector<uint8_t> visited(kept.size(), 0);
  std::vector<HullPart> parts;
  std::vector<Eigen::Vector3i> stack;
  for (int z = 0; z < grid.cells.z(); ++z)
    for (int y = 0; y < grid.cells.y(); ++y)
      for (int x = 0; x < grid.cells.x(); ++x) {
        if (!kept[grid.Index(x, y, z)] || visited[grid.Index(x, y, z)]) continue;
        HullPart part;
        visited[grid.Index(x, y, z)] = 1;
        stack.assign(1, Eigen::Vector3i(x, y, z));
        while (!stack.empty()) {
          const Eigen::Vector3i cell = stack.back();
          stack.pop_back();
          ++part.voxels;
          part.center += grid.Center(cell.x(), cell.y(), cell.z());
          for (int axis = 0; axis < 3; ++axis)
            for (int step : {-1, 1}) {
              Eigen::Vector3i next = cell;
              next[axis] += step;
              if (next[axis] < 0 || next[axis] >= grid.cells[axis]) continue;
              const size_t index = grid.Index(next.x(), next.y(), next.z());
              if (!kept[index] || visited[index]) continue;
              visited[index] = 1;
              stack.push_back(next);
            }
        }
        part.center /= double(part.voxels);
        parts.push_back(part);
      }
  std::stable_sort(parts.begin(), parts.end(),
                   [](const HullPart& a, const HullPart& b) { return a.voxels > b.voxels; });
  return parts;
}

}  // namespace

std::vector<HullProjection> ProjectHull(const std::vector<View>& views, const std::vector<Image8>& mattes,
                                        const std::vector<bool>& trusted, const std::vector<View>& targets,
                                        const MatteConsistencyOptions& options) {
  options.Check();
  std::vector<View> carve_views;
  std::vector<Image8> carve_mattes;
  for (size_t i = 0; i < views.size(); ++i)
    if (i < trusted.size() && trusted[i]) {
      carve_views.push_back(views[i]);
      carve_mattes.push_back(mattes[i]);
    }
  if (carve_views.size() < 3) Fail("a visual hull needs at least 3 trusted mattes, got ", carve_views.size());
  const CarvedHull hull = CarveTwice(carve_views, carve_mattes, options);
  const Grid& grid = hull.grid;
  std::vector<Eigen::Vector3d> surface;
  for (int z = 0; z < grid.cells.z(); ++z)
    for (int y = 0; y < grid.cells.y(); ++y)
      for (int x = 0; x < grid.cells.x(); ++x)
        if (hull.kept[grid.Index(x, y, z)] && OnSurface(grid, hull.kept, x, y, z))
          surface.push_back(grid.Center(x, y, z));
  std::vector<HullProjection> projections(targets.size());
  tbb::parallel_for(size_t(0), targets.size(), [&](size_t v) {
    const View& view = targets[v];
    cv::Mat mask = cv::Mat::zeros(view.camera.height, view.camera.width, CV_8UC1);
    for (const Eigen::Vector3d& point : surface) {
      Eigen::Vector2d pixel;
      const double depth = view.pose.ToCamera(point).z();
      projections[v].far_depth = std::max(projections[v].far_depth, depth + grid.voxel * 0.87);
      if (depth <= 0 || !view.WorldToPixel(point, &pixel)) continue;
      const int radius = int(std::ceil(view.camera.FocalX() * grid.voxel * 0.87 / depth));
      cv::circle(mask, cv::Point(int(std::floor(pixel.x())), int(std::floor(pixel.y()))), radius, 255, cv::FILLED);
    }
    // Interior voxels project inside the surface's outline: fill its holes.
    std::vector<std::vector<cv::Point>> contours;
    cv::findContours(mask, contours, cv::RETR_EXTERNAL, cv::CHAIN_APPROX_SIMPLE);
    cv::drawContours(mask, contours, -1, 255, cv::FILLED);
    Image8 out(view.camera.width, view.camera.height, 1);
    std::copy(mask.datastart, mask.dataend, out.pixels.begin());
    projections[v].mask = std::move(out);
  });
  return projections;
}

std::vector<MinorityVotes> CountMinorityVotes(const std::vector<View>& views, const std::vector<Image8>& mattes,
                                              const MatteConsistencyOptions& options) {
  options.Check();
  if (views.size() != mattes.size() || views.size() < 3) Fail("minority votes need one matte per view, 3 or more");
  const int min_seen = std::max(2, int(std::ceil(options.min_seen_fraction * double(views.size()))));
  const Eigen::Vector3d target = LookAtPoint(views);
  double distance = 0;
  for (const View& view : views) distance += (view.pose.Center() - target).norm();
  distance /= double(views.size());
  const Grid grid = MakeGrid(target - Eigen::Vector3d::Constant(0.6 * distance),
                             target + Eigen::Vector3d::Constant(0.6 * distance), options.resolution);
  const std::vector<PhotoMasks> masks = MakeAllMasks(views, mattes, options, grid);
  // Per slice of z, then summed in slice order: the same totals whatever the threads.
  std::vector<std::vector<MinorityVotes>> per_slice(grid.cells.z(), std::vector<MinorityVotes>(views.size()));
  std::vector<size_t> majority_per_slice(grid.cells.z(), 0);
  tbb::parallel_for(0, grid.cells.z(), [&](int z) {
    std::vector<int8_t> vote(views.size());
    for (int y = 0; y < grid.cells.y(); ++y)
      for (int x = 0; x < grid.cells.x(); ++x) {
        int seen = 0, tree = 0;
        for (size_t v = 0; v < views.size(); ++v) {
          cv::Point pixel;
          vote[v] = -1;
          if (!ProjectToMask(views[v], masks[v], grid.Center(x, y, z), &pixel)) continue;
          vote[v] = masks[v].dilated.at<uint8_t>(pixel) != 0;
          ++seen;
          tree += vote[v];
        }
        if (seen < min_seen || tree == 0) continue;
        const bool kept = 2 * tree >= seen;
        majority_per_slice[z] += kept;
        for (size_t v = 0; v < views.size(); ++v) {
          if (kept && vote[v] == 0) ++per_slice[z][v].carves;
          if (!kept && vote[v] == 1) ++per_slice[z][v].keeps;
        }
      }
  });
  std::vector<MinorityVotes> votes(views.size());
  size_t majority = 0;
  for (int z = 0; z < grid.cells.z(); ++z) {
    majority += majority_per_slice[z];
    for (size_t v = 0; v < views.size(); ++v) {
      votes[v].carves += per_slice[z][v].carves;
      votes[v].keeps += per_slice[z][v].keeps;
    }
  }
  for (MinorityVotes& vote : votes) vote.majority_voxels = majority;
  return votes;
}

void MatteConsistencyOptions::Check() const {
  if (!(max_second_part > 0 && max_second_part <= 1)) Fail("max second part must be in (0, 1], got ", max_second_part);
  if (resolution < 8 || resolution > 512) Fail("consistency hull resolution must be 8..512, got ", resolution);
  if (!(matte_threshold > 0 && matte_threshold < 1)) Fail("matte threshold must be in (0, 1), got ", matte_threshold);
  if (!(carve_threshold >= 0 && carve_threshold <= matte_threshold))
    Fail("carve threshold must be in [0, matte threshold ", matte_threshold, "], got ", carve_threshold);
  if (!(outvoted_fraction >= 0 && outvoted_fraction < 0.5))
    Fail("outvoted fraction must be in [0, 0.5), got ", outvoted_fraction);
  if (!(min_seen_fraction > 0 && min_seen_fraction <= 1))
    Fail("min seen fraction must be in (0, 1], got ", min_seen_fraction);
  if (max_side < 16) Fail("comparison size must be at least 16, got ", max_side);
  if (!(outvoted_share_of_seen > 0 && outvoted_share_of_seen <= 1))
    Fail("outvoted share of seen must be in (0, 1], got ", outvoted_share_of_seen);
  if (!(min_recall >= 0 && min_recall <= 1)) Fail("min recall must be in [0, 1], got ", min_recall);
  if (min_photos < 2) Fail("consistency min_photos must be at least 2, got ", min_photos);
  if (!(min_precision >= 0 && min_precision <= 1)) Fail("min precision must be in [0, 1], got ", min_precision);
}

MatteConsistency MeasureMatteConsistency(const std::vector<View>& views, const std::vector<Image8>& mattes,
                                         const MatteConsistencyOptions& options) {
  options.Check();
  if (views.size() != mattes.size() || views.size() < 3)
    Fail("matte consistency needs one matte per view and at least 3 views (", views.size(), " views, ", mattes.size(),
         " mattes)");
  CarvedHull hull = CarveTwice(views, mattes, options);
  const Grid& grid = hull.grid;
  const std::vector<uint8_t>& kept = hull.kept;
  const std::vector<PhotoMasks>& masks = hull.masks;
  MatteConsistency result;
  for (uint8_t k : kept) result.hull_voxels += k;
  result.voxel_size = grid.voxel;
  result.parts = ConnectedParts(grid, kept);

  result.photos.resize(views.size());
  tbb::parallel_for(size_t(0), views.size(), [&](size_t v) {
    const PhotoMasks& mask = masks[v];
    cv::Mat projection = cv::Mat::zeros(mask.tree.size(), CV_8UC1);
    const double depth = std::max(
        views[v].pose.ToCamera(grid.Center(grid.cells.x() / 2, grid.cells.y() / 2, grid.cells.z() / 2)).z(), 1e-9);
    const int radius =
        int(std::ceil(views[v].camera.FocalX() * mask.scale.x() * grid.voxel * 0.87 / depth));  // half-diagonal
    size_t seen = 0, on_matte = 0;
    for (int z = 0; z < grid.cells.z(); ++z)
      for (int y = 0; y < grid.cells.y(); ++y)
        for (int x = 0; x < grid.cells.x(); ++x) {
          if (!kept[grid.Index(x, y, z)]) continue;
          cv::Point pixel;
          if (!ProjectToMask(views[v], mask, grid.Center(x, y, z), &pixel)) continue;
          ++seen;
          on_matte += mask.dilated.at<uint8_t>(pixel) != 0;
          cv::circle(projection, pixel, radius, 255, cv::FILLED);
        }
    const double tree_pixels = cv::countNonZero(mask.tree);
    cv::Mat covered;
    cv::bitwise_and(mask.tree, projection, covered);
    PhotoConsistency& photo = result.photos[v];
    photo.name = views[v].name;
    photo.recall = tree_pixels > 0 ? cv::countNonZero(covered) / tree_pixels : 0.0;
    photo.precision = seen > 0 ? double(on_matte) / double(seen) : 0.0;
  });
  return result;
}

void CheckMatteConsistency(const MatteConsistency& consistency, const MatteConsistencyOptions& options,
                           const std::string& mattes_folder) {
  options.Check();
  const size_t photos = consistency.photos.size();
  if (consistency.hull_voxels == 0)
    Fail("the mattes in ", mattes_folder,
         " disagree with the cameras: no point is on the tree in (nearly) every "
         "photo, so their visual hull is empty. Check that each matte belongs to the photo of the same name, and "
         "that the cameras (sparse/) are those of these photos");
  const std::vector<HullPart>& parts = consistency.parts;
  if (parts.size() >= 2 && double(parts[1].voxels) >= options.max_second_part * double(parts[0].voxels)) {
    const auto round = [](double v) { return std::round(v * 100) / 100; };
    const auto where = [&](const Eigen::Vector3d& c) {
      return Str("(", round(c.x()), ", ", round(c.y()), ", ", round(c.z()), ")");
    };
    Fail("the mattes in ", mattes_folder, " hold two separate objects: their visual hull falls into parts of ",
         parts[0].voxels, " and ", parts[1].voxels, " voxels, around ", where(parts[0].center), " and ",
         where(parts[1].center),
         " in the cameras' frame. voltree captures one tree at a time: photograph it alone, or bring mattes "
         "that keep only the tree (the workspace's mattes/ folder)");
  }
  std::vector<PhotoConsistency> bad;
  for (const PhotoConsistency& photo : consistency.photos)
    if (photo.recall < options.min_recall || photo.precision < options.min_precision) bad.push_back(photo);
  if (bad.empty()) return;
  std::sort(bad.begin(), bad.end(), [](const PhotoConsistency& a, const PhotoConsistency& b) {
    return std::min(a.recall, a.precision) < std::min(b.recall, b.precision);
  });
  std::string list;
  for (size_t i = 0; i < bad.size() && i < 12; ++i)
    list += Str("\n  ", bad[i].name, ": recall ", std::round(bad[i].recall * 1000) / 1000, ", precision ",
                std::round(bad[i].precision * 1000) / 1000);
  if (bad.size() > 12) list += Str("\n  ... (", bad.size(), " in all)");
  Fail("the mattes in ", mattes_folder, " disagree with the cameras in ", bad.size(), " of ", photos,
       " photos (the visual hull of all mattes, projected back; limits: recall ", options.min_recall, ", precision ",
       options.min_precision, "):", list,
       "\nLow recall: the matte holds what no other photo agrees is tree (ground or sky taken for it). Low "
       "precision: the matte misses what the others agree on (the tree cut out, another photo's matte, or a "
       "camera that is off). ",
       bad.size() * 2 > photos ? "When most photos disagree, the mattes may not belong to these photos or cameras. "
                               : "",
       "Fix or remove those mattes (voltree matte --force, or --mattes FOLDER), or leave those photos out");
}

}  // namespace voltree
