// Codebooks already trained on one volume's billboards with one set of options, by size, and the
// training sets they were trained on. The byte budget compresses the same volume at several pairs
// of codebook sizes; a size trained once is reused (GLA is deterministic, so the result is the
// same as training it again), and the vectors are built once.
#pragma once

#include <map>
#include <optional>

#include "compress/gla.h"
#include "compress/training_set.h"

namespace voltree {

struct TrainedCodebooks {
  std::map<int, GlaResult> colour;  // by requested codebook size
  std::map<int, GlaResult> alpha;
  std::optional<TrainingSet> colour_set, alpha_set;
};

}  // namespace voltree
