#include "capture/matte/coverage.h"

#include <cmath>

#include "core/error.h"

namespace voltree {
namespace {

std::string Percent(double fraction) { return Str(std::round(1000 * fraction) / 10, " %"); }

std::string List(const std::vector<NamedCoverage>& mattes) {
  std::string joined;
  for (size_t i = 0; i < mattes.size() && i < 12; ++i)
    joined += Str(i ? ", " : "", mattes[i].name, " (", Percent(mattes[i].coverage), ")");
  if (mattes.size() > 12) joined += Str(", ... (", mattes.size(), " in all)");
  return joined;
}

}  // namespace

void MatteCoverageLimits::Check() const {
  if (!(min_coverage >= 0 && min_coverage < max_coverage && max_coverage <= 1))
    Fail("matte coverage limits must satisfy 0 <= min (", min_coverage, ") < max (", max_coverage, ") <= 1");
}

double MatteCoverage(const Image8& matte) {
  if (matte.channels != 1) Fail("a matte must have one channel, got ", matte.channels);
  uint64_t sum = 0;
  for (uint8_t a : matte.pixels) sum += a;
  return matte.pixels.empty() ? 0.0 : double(sum) / (255.0 * double(matte.pixels.size()));
}

void CheckMatteCoverage(const std::vector<NamedCoverage>& mattes, const MatteCoverageLimits& limits,
                        const std::string& source, bool computed) {
  limits.Check();
  std::vector<NamedCoverage> too_much, too_little;
  for (const NamedCoverage& matte : mattes) {
    if (matte.coverage > limits.max_coverage) too_much.push_back(matte);
    if (matte.coverage < limits.min_coverage) too_little.push_back(matte);
  }
  if (too_much.empty() && too_little.empty()) return;
  std::string message = Str("the mattes (", source, ") cannot be right; nothing was written.");
  if (!too_much.empty())
    message += Str("\n  ", too_much.size(), " of ", mattes.size(), " cover more than ", Percent(limits.max_coverage),
                   " of the frame: ", List(too_much));
  if (!too_little.empty())
    message += Str("\n  ", too_little.size(), " of ", mattes.size(), " cover less than ", Percent(limits.min_coverage),
                   " of the frame: ", List(too_little));
  if (computed)
    message +=
        "\nA matte that covers most of the frame took the ground or the sky for the tree; one that covers "
        "almost nothing found no tree. Try --horizon ROW (the horizon's row as a fraction of the height, "
        "where the ground behind the tree begins), --refine guided, or bring your own mattes with "
        "--mattes FOLDER; leave photos without the tree out of images/.";
  else
    message +=
        "\nCheck that each matte belongs to the photo of the same name and is white (255) on the tree "
        "and black (0) elsewhere.";
  Fail(message);
}

}  // namespace voltree
