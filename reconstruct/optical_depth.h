// The optical depth b = -ln(max(1 - alpha, epsilon)) of a pixel's alpha: the right-hand side of the
// tomography and the quantity the billboards split among the cells on a ray. Both must use the
// same epsilon, or compositing the billboards would not reproduce the alpha the tomography fitted.
#pragma once

#include <algorithm>
#include <cmath>

namespace voltree {

// Caps b at -ln(epsilon) (about 6.9), so that an opaque pixel has a finite optical depth.
inline constexpr double kDefaultAlphaEpsilon = 1e-3;

inline double OpticalDepth(double alpha, double epsilon) { return -std::log(std::max(1.0 - alpha, epsilon)); }

}  // namespace voltree
