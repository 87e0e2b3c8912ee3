// Codebooks already trained on one volume's billboards with one set of options, by size. The byte
// budget compresses the same volume at several pairs of codebook sizes; a size trained once is
// reused (GLA is deterministic, so the result is the same as training it again).
#pragma once

#include <map>

#include "compress/gla.h"

namespace voltree {

struct TrainedCodebooks {
  std::map<int, GlaResult> colour;  // by requested codebook size
  std::map<int, GlaResult> alpha;
};

}  // namespace voltree
