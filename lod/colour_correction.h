// The pruned tree's leaf colours, corrected so that its colour statistics match the full tree's
// (Neubert et al. 2011, sec. 5, which shows that pruning keeps large colour regions but quantizes
// smooth gradations and small salient details; and the contrast correction of Cook et al. 2007,
// which their recap names). Two parts:
//  - mean: the survivors' mean colour, weighted by their drawn area, is moved to the full tree's
//    area-weighted mean (a priority order that is not random can favour some colours);
//  - contrast: a distant pixel averages the colours of the n leaves it covers, with variance
//    sigma^2 / n; after pruning to lambda with scaling it averages lambda * n bigger leaves, with
//    variance sigma^2 / (lambda n). Scaling each survivor's deviation from the mean by sqrt(lambda)
//    gives the pixels back the full tree's variance.
// The colour is changed through the leaf's vertex tint, which multiplies its material colour.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "lod/leaf_separation.h"
#include "lod/pruned_mesh.h"
#include "samples/tree_mesh.h"

namespace voltree {

// The drawn leaves' corrected colours (linear RGB), in the order of `draws`: mean + contrast *
// (colour - survivors' mean), where mean is the full tree's. `colours` are every leaf's
// (LeafColours). Throws Error for a leaf index out of range or contrast outside [0, 1].
std::vector<Eigen::Vector3f> CorrectedLeafColours(const std::vector<Eigen::Vector3f>& colours,
                                                  const std::vector<Leaf>& leaves, const std::vector<LeafDraw>& draws,
                                                  double contrast);

// Cook's contrast factor for a kept fraction lambda: sqrt(lambda).
double ContrastFactor(double lambda);

// A copy of `mesh` whose drawn leaves' vertex tints are multiplied, channel by channel, so that
// each leaf's colour goes from colours[leaf] to corrected[k] (draws[k] the leaf); a channel that is
// black stays as it is.
TreeMesh WithLeafColours(const TreeMesh& mesh, const std::vector<Leaf>& leaves, const std::vector<LeafDraw>& draws,
                         const std::vector<Eigen::Vector3f>& colours, const std::vector<Eigen::Vector3f>& corrected);

}  // namespace voltree
