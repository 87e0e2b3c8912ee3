// Clustered ellipsoids' branches (Clasen, Paar and Prohaska, sec. 3.2): the skeleton's segments
// are merged bottom-up, two at a time, until one line is left. "Straighten" replaces two
// consecutive segments by one (the node between them goes); "combine" replaces two sibling tips by
// their average, weighted by the segments' volumes, which the merged segment inherits as their
// sum. Either keeps the graph one connected tree. Where we depart: the paper picks each merge by
// the image error of random candidate pairs; here the merge that moves the geometry least (the
// removed node's distance from the new segment) goes first, and a screen size applies the merges
// that move it less than a pixel.
#pragma once

#include <cstddef>
#include <vector>

#include "lod/branch_skeleton.h"

namespace voltree {

struct LineMerge {
  enum class Kind { kStraighten, kCombine } kind = Kind::kStraighten;
  int removed = 0;  // the node that goes
  int kept = 0;     // straighten: the removed node's child; combine: the sibling kept
  double cost = 0;  // how far the merge moves the geometry, in mesh units
};

struct LineHierarchy {
  BranchSkeleton skeleton;        // the finest level
  std::vector<LineMerge> merges;  // in order, down to one segment
};

LineHierarchy SimplifyLines(const BranchSkeleton& skeleton);

// The skeleton after the first `merges` merges, renumbered (parents still first).
BranchSkeleton LinesAfter(const LineHierarchy& hierarchy, size_t merges);

// How many merges move the geometry by no more than `max_cost`: the leading run of the sequence.
size_t MergesWithin(const LineHierarchy& hierarchy, double max_cost);

}  // namespace voltree
