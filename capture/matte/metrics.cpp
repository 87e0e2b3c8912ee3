#include "capture/matte/metrics.h"

#include <cmath>
#include <cstdlib>

#include "core/error.h"

namespace voltree {

MatteError CompareMattes(const Image8& estimate, const Image8& truth) {
  if (estimate.channels != 1 || truth.channels != 1)
    Fail("CompareMattes: expected 1-channel mattes, got ", estimate.channels, " and ", truth.channels);
  if (estimate.width != truth.width || estimate.height != truth.height)
    Fail("CompareMattes: matte is ", estimate.width, "x", estimate.height, " but the truth is ", truth.width, "x",
         truth.height);
  // Integer sums: exact and order-independent.
  uint64_t sum_abs = 0, sum_sq = 0, band_sq = 0, band = 0;
  for (size_t i = 0; i < truth.pixels.size(); ++i) {
    const int a = estimate.pixels[i], b = truth.pixels[i];
    const uint64_t d = static_cast<uint64_t>(std::abs(a - b));
    sum_abs += d;
    sum_sq += d * d;
    const bool fractional = (a != 0 && a != 255) || (b != 0 && b != 255);
    if (fractional || d > 1) {
      band_sq += d * d;
      ++band;
    }
  }
  MatteError error;
  const double n = static_cast<double>(truth.pixels.size());
  error.sad = static_cast<double>(sum_abs) / 255.0 / 1000.0;
  error.mse = n > 0 ? static_cast<double>(sum_sq) / (255.0 * 255.0) / n * 1e3 : 0.0;
  error.mse_band = band > 0 ? static_cast<double>(band_sq) / (255.0 * 255.0) / double(band) * 1e3 : 0.0;
  error.band_pixels = band;
  return error;
}

}  // namespace voltree
