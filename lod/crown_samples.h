// Sample points on a tree's crown hull for Neubert et al. 2011's occlusion test (sec. 4): the
// paper tests points "distributed on its iso-surface", the zero iso-surface of the metaballs of
// radius r at the leaf centres (rendering_priority.h). We take, for each of `count` directions d
// spread over the sphere, the leaf centre p farthest along d and the point p + r d: no metaball
// reaches past the plane through it with normal d, so the point lies on that iso-surface, and
// every leaf centre of the tree lies behind the plane. Seen from an eye in front of the plane
// (d . (eye - point) > 0) the tree's own leaves cannot hide the point, so a test against a depth
// buffer counts only what other trees (or the ground) hide.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "lod/leaf_separation.h"

namespace voltree {

struct CrownSample {
  Eigen::Vector3f point = Eigen::Vector3f::Zero();    // on the hull, in the mesh's frame
  Eigen::Vector3f normal = Eigen::Vector3f::UnitZ();  // the direction it was found for (outward, unit)
};

// `count` samples (duplicates kept: each direction is one vote), directions on a Fibonacci sphere
// turned about +Z by an angle from `seed`. Empty without leaves. Throws Error for count < 1 or
// radius < 0.
std::vector<CrownSample> CrownHullSamples(const std::vector<Leaf>& leaves, double radius, int count, uint64_t seed);

}  // namespace voltree
