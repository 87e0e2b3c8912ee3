#include "compress/texture_psnr.h"

#include <cmath>
#include <limits>

#include "core/error.h"

namespace voltree {

double MeanSquaredError(const std::vector<uint8_t>& reference, const std::vector<uint8_t>& test) {
  if (reference.size() != test.size() || reference.empty())
    Fail("PSNR: ", reference.size(), " reference bytes vs ", test.size(), " test bytes");
  uint64_t sum = 0;
  for (size_t i = 0; i < reference.size(); ++i) {
    const int d = int(reference[i]) - int(test[i]);
    sum += uint64_t(d * d);
  }
  return double(sum) / double(reference.size());
}

double Psnr(const std::vector<uint8_t>& reference, const std::vector<uint8_t>& test) {
  const double mse = MeanSquaredError(reference, test);
  return mse > 0 ? 10 * std::log10(255.0 * 255.0 / mse) : std::numeric_limits<double>::infinity();
}

}  // namespace voltree
