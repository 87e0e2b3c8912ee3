// The largest codebooks whose asset fits a byte budget on disk.
//
// The codeword indices are most of an asset's bytes (a few bits per billboard, hundreds of
// thousands of billboards), so the budget is met by halving both codebooks until the serialized
// asset fits. New viewpoints barely tell 64 codewords from 512 on a dense tree, the input views
// and sparse trees do (2048 against 512: +1.1 to +1.4 dB alpha at the input views of the pine,
// the young oak and the aspen): the codebooks stay as large as the budget allows, and a small
// tree keeps the full size.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "compress/compress_volume.h"
#include "core/progress.h"
#include "core/volume.h"
#include "core/vtree.h"

namespace voltree {

struct BudgetedCompression {
  CompressResult result;  // the asset, its codebooks and statistics as kept
  CompressOptions kept;   // the options of the attempt kept (its codebook sizes)
  std::string bytes;      // the asset serialized
  bool fits = true;       // false: over the budget even at the smallest codebooks tried
  int attempts = 1;       // compressions run
};

// Finishes an asset (provenance) and serializes it; called once per attempt.
using AssetSerializer = std::function<std::string(VtreeAsset&)>;

// The first rung of `ladder` (codebook pairs, largest first) that the budget tries: the largest whose
// index bits alone fit max_bytes (0: the first). Each billboard stores a colour and an alpha index,
// which are most of a large asset's bytes and compress little (the demo oak at 128 / 128: 960 KB of
// index bits in a 1 049 KB file), so the boundary is usually this rung or the next, and no rung far
// too large is compressed for nothing.
size_t PredictedRung(const std::vector<std::pair<int, int>>& ladder, size_t billboards, uint64_t max_bytes);

// Compresses `volume` with the largest codebooks whose serialized asset fits options.max_bytes
// (0: no budget, options' codebooks as given): options' sizes, or both halved, down to
// options.smallest_budget_codebook. Where the budget binds and options.trade_codebooks is set,
// colour codewords are then traded for alpha ones while the texture PSNR gains (the alpha
// codebook doubled, the colour one the largest that still fits, down to 16). Deterministic: the
// same volume and options give the same attempts and bytes.
BudgetedCompression CompressWithinBudget(const Volume& volume, const CompressOptions& options,
                                         const AssetSerializer& serialize, Progress* progress = nullptr);

}  // namespace voltree
