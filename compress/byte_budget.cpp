#include "compress/byte_budget.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <utility>
#include <vector>

#include "compress/trained_codebooks.h"
#include "core/error.h"

namespace voltree {
namespace {

// The next smaller codebook: half, but not below `floor`; a codebook at or below it stays.
int Halved(int size, int floor) { return size > floor ? std::max(size / 2, floor) : size; }

// The codebook sizes a budget may try, largest first: options', then both halved down to the floor.
std::vector<std::pair<int, int>> CodebookLadder(const CompressOptions& options) {
  std::vector<std::pair<int, int>> ladder = {{options.colour_codebook, options.alpha_codebook}};
  for (;;) {
    const auto [colour, alpha] = ladder.back();
    const std::pair<int, int> next = {Halved(colour, options.smallest_budget_codebook),
                                      Halved(alpha, options.smallest_budget_codebook)};
    if (next == ladder.back()) return ladder;
    ladder.push_back(next);
  }
}

// The budget binds at `best` (equal sizes). An alpha codeword is worth more than a colour one
// where the leaves' colours are few and their shapes many (the demo oak: 16 / 1024 fits where
// 128 / 512 does not, as alpha indices compress worse, and gains 0.9 dB texture PSNR over
// 256 / 256). So for each doubling of the alpha codebook, up to `largest_alpha`, the largest
// colour codebook that still fits, no larger than the last pair's, is found by bisection, down to
// kSmallestTradedColour; the pair with the best texture PSNR (as the renderer fetches it) is kept.
// The search stops at the first alpha size that gains nothing or for which no colour codebook fits.
// A pair known not to fit is not compressed: doubling the alpha codebook alone adds at least half a
// bit per billboard (the oak: 1.4 bits), so the last pair's colour size is skipped when that would
// not fit, which spares training an alpha codebook twice the size for nothing.
template <class Attempt>
BudgetedCompression TradeColourForAlpha(BudgetedCompression best, int largest_alpha, uint64_t max_bytes,
                                        const Attempt& attempt) {
  constexpr int kSmallestTradedColour = 16;
  int colour_limit = best.kept.colour_codebook;  // a larger alpha codebook leaves room for no more colour
  for (int alpha = best.kept.alpha_codebook * 2; alpha <= largest_alpha; alpha *= 2) {
    const uint64_t same_colour_at_least = best.bytes.size() + best.result.stats.billboards / 16;
    std::vector<int> colours;  // descending, so the assets' sizes descend too
    for (int colour = same_colour_at_least > max_bytes ? colour_limit / 2 : colour_limit;
         colour >= kSmallestTradedColour; colour /= 2)
      colours.push_back(colour);
    std::optional<BudgetedCompression> fitting;
    size_t low = 0, high = colours.size();  // the first index that fits, or colours.size()
    while (low < high) {
      const size_t middle = (low + high) / 2;
      BudgetedCompression tried = attempt(colours[middle], alpha);
      if (tried.fits) {
        high = middle;
        fitting = std::move(tried);
      } else {
        low = middle + 1;
      }
    }
    if (!fitting || fitting->result.stats.psnr_dxt5 <= best.result.stats.psnr_dxt5) break;
    colour_limit = fitting->kept.colour_codebook;
    best = std::move(*fitting);
  }
  return best;
}

}  // namespace

size_t PredictedRung(const std::vector<std::pair<int, int>>& ladder, size_t billboards, uint64_t max_bytes) {
  if (max_bytes == 0) return 0;
  for (size_t rung = 0; rung < ladder.size(); ++rung) {
    const double bits = std::ceil(std::log2(ladder[rung].first)) + std::ceil(std::log2(ladder[rung].second));
    if (double(billboards) * bits / 8 <= double(max_bytes)) return rung;
  }
  return ladder.size() - 1;
}

BudgetedCompression CompressWithinBudget(const Volume& volume, const CompressOptions& options,
                                         const AssetSerializer& serialize, Progress* progress) {
  const std::vector<std::pair<int, int>> ladder =
      options.max_bytes == 0 ? std::vector<std::pair<int, int>>{{options.colour_codebook, options.alpha_codebook}}
                             : CodebookLadder(options);
  int attempts = 0;
  TrainedCodebooks trained;  // each size is trained once, whatever pairs it is tried in
  const auto attempt = [&](int colour, int alpha) {
    BudgetedCompression out;
    out.kept = options;
    out.kept.colour_codebook = colour;
    out.kept.alpha_codebook = alpha;
    out.result = CompressVolume(volume, out.kept, progress, &trained);
    out.bytes = serialize(out.result.asset);
    out.fits = options.max_bytes == 0 || out.bytes.size() <= options.max_bytes;
    ++attempts;
    if (progress && options.max_bytes != 0)
      progress->Say("compress", Str(out.bytes.size(), " bytes with codebooks ", colour, " / ", alpha,
                                    (out.fits ? ": within" : ": over"), " the budget of ", options.max_bytes,
                                    " bytes; texture PSNR ", out.result.stats.psnr_dxt5, " dB"));
    return out;
  };
  // Smaller codebooks make smaller files (fewer bits per index), so the largest rung that fits is
  // found by walking from the rung the index bits predict to the boundary: usually one or two
  // compressions, and none of a rung far too large to fit (the oak's 512 / 512: 18 s). The
  // smallest rung is kept when none fits.
  size_t rung = PredictedRung(ladder, CountBillboards(volume), options.max_bytes);
  BudgetedCompression kept = attempt(ladder[rung].first, ladder[rung].second);
  if (kept.fits) {
    while (rung > 0) {  // larger codebooks while they fit
      BudgetedCompression larger = attempt(ladder[rung - 1].first, ladder[rung - 1].second);
      if (!larger.fits) break;
      kept = std::move(larger);
      --rung;
    }
  } else {
    while (!kept.fits && rung + 1 < ladder.size()) {  // smaller ones until one fits
      ++rung;
      kept = attempt(ladder[rung].first, ladder[rung].second);
    }
  }
  // rung > 0: the rung above was over, so the budget binds here.
  if (options.trade_codebooks && options.max_bytes != 0 && kept.fits && rung > 0)
    kept = TradeColourForAlpha(std::move(kept), options.alpha_codebook, options.max_bytes, attempt);
  kept.attempts = attempts;
  return kept;
}

}  // namespace voltree
