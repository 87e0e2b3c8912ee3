// Opacity estimation on the hierarchy, coarse to fine: at each level carve the candidates by the
// visual hull, initialise each cell from its parent, solve the level's tomography (SART or
// Ceres), and refine only the cells dense enough to matter. After the finest solve every coarser
// level is rebuilt from it: a parent's sigma is the mean of its children's, so a ray crossing the
// whole parent keeps its optical depth.
#pragma once

#include <string>
#include <vector>

#include "core/camera.h"
#include "core/progress.h"
#include "reconstruct/ceres_solve.h"
#include "reconstruct/grid.h"
#include "reconstruct/matte_stats.h"
#include "reconstruct/sart.h"
#include "reconstruct/tomography.h"

namespace voltree {

enum class SolverKind { kSart, kCeres };

struct OpacityOptions {
  SolverKind solver = SolverKind::kSart;
  TomographyOptions tomography;
  SartOptions sart;
  CeresSolveOptions ceres;
  // A cell is refined when sigma * cell edge (its optical depth) reaches this; below it the cell
  // is practically transparent (alpha < 0.2 %).
  double refine_min_optical_depth = 0;  // 0: refine every cell the visual hull keeps
  // A cell is carved when this many views each see all of it empty. 1 is the strict visual hull;
  // 2 lets one wrong matte (a trunk cut off against soil of its colour) leave the tree standing,
  // but keeps cells that only one view could carve, which blurs a dense crown's edge.
  int carve_views = 1;

  void Check() const;  // throws OptionError naming the field
};

struct OpacityLevel {
  std::vector<CellCoord> cells;  // sorted by CellLess
  std::vector<float> density;
};

struct OpacityLevelReport {
  size_t candidates = 0, kept = 0, rays = 0, entries = 0;
  bool stored = false;
  SolveReport solve;
};

struct OpacityResult {
  std::vector<OpacityLevel> levels;  // final, consistent with the finest level
  std::vector<OpacityLevel> solved;  // each level as solved, before the rebuild
  std::vector<OpacityLevelReport> reports;
};

// When levels beyond the first `required` are added: only while the cells of non-zero sigma of
// the levels solved, and the next level's predicted as `growth` times the finest's, stay within
// `max_cells` (a thin branch's cells double or so per level, a leafy surface's quadruple).
struct DeepeningRule {
  int required = 1;
  size_t max_cells = 0;
  double growth = 4;
};

// Levels 0 .. levels-1 of the hierarchy, coarse to fine; with `deepening`, fewer where it stops
// (the result then has as many levels as were solved).
OpacityResult EstimateOpacity(const GridFrame& frame, const std::vector<View>& views,
                              const std::vector<MatteStats>& mattes, int levels, const OpacityOptions& options,
                              Progress* progress, const DeepeningRule* deepening = nullptr);

// Levels 0 .. finest-1 rebuilt from `finest` (cells at level `finest_level`): parent sigma = sum of
// the children's sigma / branching^3. Cells with zero sigma are dropped first.
std::vector<OpacityLevel> BuildHierarchyFromFinest(const OpacityLevel& finest, int finest_level, int branching);

}  // namespace voltree
