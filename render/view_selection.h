// Which input views' billboards to draw: the two whose direction towards the tree is closest in
// angle to the current one (Reche 2004), weighted by angular distance.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "core/vtree.h"

namespace voltree {

struct ViewPair {
  int first = 0, second = 0;                  // view indices; equal when the asset has one view
  float first_weight = 1, second_weight = 0;  // sum to 1; the nearer view weighs more
};

// Angles are between (centre - eye) and (centre - view.position) for each input view, so views
// are compared by where they look at the tree from. Ties go to the lower index (deterministic).
// Weights: w_first = a2 / (a1 + a2), w_second = a1 / (a1 + a2) (1 and 0 when a1 = a2 = 0).
ViewPair SelectViews(const std::vector<VtreeView>& views, const Eigen::Vector3d& centre, const Eigen::Vector3d& eye);

}  // namespace voltree
