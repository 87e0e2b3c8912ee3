#include "lod/screen_size_rule.h"

#include <algorithm>

#include "core/error.h"

namespace voltree {

double LambdaForScreenSize(double size, double full_size, double min_lambda) {
  if (!(full_size > 0) || !(size > 0) || size > full_size)
    Fail("lod: screen size ", size, " is not in (0, ", full_size, "]");
  if (!(min_lambda > 0 && min_lambda <= 1)) Fail("lod: the smallest lambda ", min_lambda, " is outside (0, 1]");
  const double ratio = size / full_size;
  return std::clamp(ratio * ratio, min_lambda, 1.0);
}

}  // namespace voltree
