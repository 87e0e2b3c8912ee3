#include "compress/byte_budget.h"

#include <algorithm>
#include <optional>
#include <tuple>
#include <utility>
#include <vector>

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

}  // namespace

BudgetedCompression CompressWithinBudget(const Volume& volume, const CompressOptions& options,
                                         const AssetSerializer& serialize, Progress* progress) {
  const std::vector<std::pair<int, int>> ladder =
      options.max_bytes == 0 ? std::vector<std::pair<int, int>>{{options.colour_codebook, options.alpha_codebook}}
                             : CodebookLadder(options);
  int attempts = 0;
  const auto attempt = [&](size_t rung) {
    BudgetedCompression out;
    out.kept = options;
    std::tie(out.kept.colour_codebook, out.kept.alpha_codebook) = ladder[rung];
    out.result = CompressVolume(volume, out.kept, progress);
    out.bytes = serialize(out.result.asset);
    out.fits = options.max_bytes == 0 || out.bytes.size() <= options.max_bytes;
    ++attempts;
    if (progress && options.max_bytes != 0)
      progress->Say("compress",
                    Str(out.bytes.size(), " bytes with codebooks ", ladder[rung].first, " / ", ladder[rung].second,
                        (out.fits ? ": within" : ": over"), " the budget of ", options.max_bytes, " bytes"));
    return out;
  };
  // Smaller codebooks make smaller files (fewer bits per index), so the largest rung that fits is
  // found by bisection: two or three compressions instead of one per rung. The smallest rung is
  // kept when none fits.
  size_t low = 0, high = ladder.size() - 1;
  std::optional<BudgetedCompression> at_high;
  while (low < high) {
    const size_t middle = (low + high) / 2;
    BudgetedCompression tried = attempt(middle);
    if (tried.fits) {
      high = middle;
      at_high = std::move(tried);
    } else {
      low = middle + 1;
    }
  }
  if (!at_high || at_high->kept.colour_codebook != ladder[high].first ||
      at_high->kept.alpha_codebook != ladder[high].second)
    at_high = attempt(high);
  at_high->attempts = attempts;
  return std::move(*at_high);
}

}  // namespace voltree
