// The Generalized Lloyd Algorithm (Linde-Buzo-Gray; Linz 2006 section 4.1) for vector
// quantization: k-means++ seeding, Lloyd iterations until the relative drop in distortion falls
// below a tolerance, empty cells re-seeded from the worst cell. The modified GLA of Linz 2006
// replaces each final centroid by the cluster member closest to it, which keeps the contrast and
// brightness that averaging loses.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "compress/kmeans_plus_plus.h"
#include "compress/training_set.h"

namespace voltree {

enum class CodewordRule {
  kCentroid,       // classic GLA: the cluster mean
  kClosestMember,  // modified GLA: the training vector closest to the cluster mean
};

CodewordRule ParseCodewordRule(const std::string& name);  // "classic" | "modified"
std::string CodewordRuleName(CodewordRule rule);

struct GlaOptions {
  int codebook_size = 512;  // clamped to the number of training vectors
  CodewordRule rule = CodewordRule::kClosestMember;
  double tolerance = 1e-3;  // stop when (D_prev - D) / D_prev < tolerance
  int max_iterations = 40;
  uint64_t seed = 1;
  int seeding_trials = 3;  // k-means++ candidates per centre, best kept (greedy k-means++, as OpenCV)

  void Check() const;
};

struct GlaResult {
  Codebook codebook;
  std::vector<uint32_t> assignment;        // nearest final codeword of every training vector
  std::vector<double> distortion_history;  // mean distortion after each Lloyd assignment
  double distortion = 0;                   // mean distortion with the final codebook
  int iterations = 0;
  int reseeded = 0;  // empty cells re-seeded, over all iterations
};

// Called after every Lloyd iteration with (iteration, mean distortion).
using GlaObserver = std::function<void(int, double)>;

GlaResult RunGla(const TrainingSet& set, const GlaOptions& options, const GlaObserver& observer = {});
// The same from a given initial codebook (its size overrides options.codebook_size).
GlaResult RunGlaFrom(const TrainingSet& set, const GlaOptions& options, Codebook initial,
                     const GlaObserver& observer = {});

// The mean (weighted per component when the set has weights) of the given members.
void ClusterMean(const TrainingSet& set, const uint32_t* members, size_t count, float* mean);

// Mean distortion of `set` quantized with `codebook` (nearest codeword).
double MeanDistortion(const Codebook& codebook, const TrainingSet& set);

}  // namespace voltree
