#include "compress/training_set.h"

#include <cmath>

#include "core/error.h"

namespace voltree {

void TrainingSet::Check() const {
  if (dimension <= 0) Fail("training set: dimension must be positive, got ", dimension);
  if (vectors.size() % dimension != 0)
    Fail("training set: ", vectors.size(), " values is not a multiple of the dimension ", dimension);
  if (weighted() && weights.size() != vectors.size())
    Fail("training set: ", weights.size(), " weights for ", vectors.size(), " values");
  for (float v : vectors)
    if (!std::isfinite(v)) Fail("training set: a value is not finite");
  for (float w : weights)
    if (!(w >= 0) || !std::isfinite(w)) Fail("training set: weights must be finite and >= 0");
}

}  // namespace voltree
