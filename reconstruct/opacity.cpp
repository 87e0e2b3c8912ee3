#include "reconstruct/opacity.h"

#include <algorithm>
#include <numeric>

#include "core/error.h"
#include "reconstruct/carve.h"

namespace voltree {

std::vector<OpacityLevel> BuildHierarchyFromFinest(const OpacityLevel& finest, int finest_level, int branching) {
  std::vector<OpacityLevel> levels(finest_level + 1);
  OpacityLevel& last = levels[finest_level];
  for (size_t i = 0; i < finest.cells.size(); ++i)
    if (finest.density[i] > 0) {
      last.cells.push_back(finest.cells[i]);
      last.density.push_back(finest.density[i]);
    }
  const double children = double(branching) * branching * branching;
  for (int level = finest_level - 1; level >= 0; --level) {
    const OpacityLevel& child = levels[level + 1];
    std::vector<std::pair<CellCoord, size_t>> parents(child.cells.size());
    for (size_t i = 0; i < child.cells.size(); ++i) {
      const CellCoord& c = child.cells[i];
      parents[i] = {CellCoord{uint16_t(c[0] / branching), uint16_t(c[1] / branching), uint16_t(c[2] / branching)}, i};
    }
    std::stable_sort(parents.begin(), parents.end(),
                     [](const auto& a, const auto& b) { return CellLess(a.first, b.first); });
    OpacityLevel& out = levels[level];
    for (size_t i = 0; i < parents.size();) {
      double sum = 0;
      size_t j = i;
      for (; j < parents.size() && parents[j].first == parents[i].first; ++j) sum += child.density[parents[j].second];
      out.cells.push_back(parents[i].first);
      out.density.push_back(float(sum / children));
      i = j;
    }
  }
  return levels;
}

OpacityResult EstimateOpacity(const GridFrame& frame, const std::vector<View>& views,
                              const std::vector<MatteStats>& mattes, int levels, const OpacityOptions& options,
                              Progress* progress, const DeepeningRule* deepening) {
  OpacityResult result;
  size_t cells_so_far = 0;
  std::vector<CellCoord> candidates = {CellCoord{0, 0, 0}};
  std::vector<double> initial = {0.0};
  int finest = -1;
  for (int level = 0; level < levels && !candidates.empty(); ++level) {
    OpacityLevelReport report;
    report.candidates = candidates.size();
    std::vector<CellCoord> kept = CarveCells(frame, level, candidates, views, mattes, options.carve_views);
    report.kept = kept.size();
    if (kept.empty()) {
      if (level == 0)
        Fail(
            "nothing to reconstruct: the visual hull of the mattes is empty (no view sees the tree inside the bounds)");
      break;
    }
    // Initial sigma: the parent's (candidates and `initial` are parallel; kept is a subsequence).
    std::vector<double> x;
    x.reserve(kept.size());
    for (size_t i = 0, j = 0; i < kept.size(); ++i) {
      while (candidates[j] != kept[i]) ++j;
      x.push_back(initial[j]);
    }
    const LevelCells cells(frame.Resolution(level), std::move(kept));
    const TomographySystem system(frame, level, cells, views, mattes, options.tomography);
    report.rays = system.ray_count();
    report.entries = system.entry_count();
    report.stored = system.stored();
    report.solve = options.solver == SolverKind::kCeres ? SolveCeres(system, options.ceres, &x)
                                                        : SolveSart(system, options.sart, &x);
    if (progress)
      progress->Say("reconstruct",
                    Str("level ", level, ": ", cells.resolution(), "^3 grid, ", cells.size(), " of ", report.candidates,
                        " candidate cells kept, ", report.rays, " rays, ", report.entries, " entries (",
                        report.stored ? "stored" : "streamed", "), ", report.solve.iterations, " ",
                        options.solver == SolverKind::kCeres ? "Ceres" : "SART", " iterations, rms residual ",
                        report.solve.rms_residual));
    OpacityLevel solved{cells.cells(), std::vector<float>(x.begin(), x.end())};
    result.reports.push_back(report);
    finest = level;

    // Cells of zero sigma get no billboards (the hierarchy is rebuilt from the finest without them).
    const size_t alive = size_t(std::count_if(x.begin(), x.end(), [](double sigma) { return sigma > 0; }));
    cells_so_far += alive;
    if (deepening != nullptr && level + 1 >= deepening->required && level + 1 < levels) {
      const size_t predicted = cells_so_far + size_t(deepening->growth * double(alive));
      const bool deeper = predicted <= deepening->max_cells;
      if (progress)
        progress->Say("reconstruct", Str(deeper ? "one level more" : "no more levels", ": level ", level + 1,
                                         " would bring the octree to about ", predicted, " cells, ",
                                         deeper ? "within" : "over", " the byte budget's ", deepening->max_cells));
      if (!deeper) levels = level + 1;
    }
    // Refine the dense cells; their children start from the parent's sigma.
    candidates.clear();
    initial.clear();
    if (level + 1 < levels) {
      const double cell = frame.CellSize(level);
      std::vector<CellCoord> dense;
      std::vector<double> dense_sigma;
      for (size_t i = 0; i < solved.cells.size(); ++i)
        if (x[i] * cell >= options.refine_min_optical_depth) {
          dense.push_back(solved.cells[i]);
          dense_sigma.push_back(x[i]);
        }
      const int b = frame.branching;
      candidates = Children(dense, b);
      // Children() sorts; look the parent up by coordinates.
      const LevelCells parents(cells.resolution(), dense);
      initial.resize(candidates.size());
      for (size_t i = 0; i < candidates.size(); ++i) {
        const CellCoord& c = candidates[i];
        initial[i] = dense_sigma[parents.Find(c[0] / b, c[1] / b, c[2] / b)];
      }
    }
    result.solved.push_back(std::move(solved));
  }
  result.levels = BuildHierarchyFromFinest(result.solved[finest], finest, frame.branching);
  result.levels.resize(levels);  // levels never reached stay empty
  return result;
}

void OpacityOptions::Check() const {
  if (solver != SolverKind::kSart && solver != SolverKind::kCeres)
    FailOption("OpacityOptions.solver", "is not a known solver (", int(solver), ")");
  if (!(refine_min_optical_depth >= 0))
    FailOption("OpacityOptions.refine_min_optical_depth", "must be >= 0, got ", refine_min_optical_depth);
  if (carve_views < 1) FailOption("OpacityOptions.carve_views", "must be >= 1, got ", carve_views);
  tomography.Check();
  sart.Check();
  ceres.Check();
}

}  // namespace voltree
