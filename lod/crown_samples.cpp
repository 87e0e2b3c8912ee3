#include "lod/crown_samples.h"

#include <cmath>
#include <numbers>

#include "core/error.h"
#include "lod/seeded_random.h"

namespace voltree {

std::vector<CrownSample> CrownHullSamples(const std::vector<Leaf>& leaves, double radius, int count, uint64_t seed) {
  if (count < 1) Fail("lod: ", count, " crown samples; expected 1 or more");
  if (!(radius >= 0)) Fail("lod: crown hull radius ", radius, " is negative");
  std::vector<CrownSample> samples;
  if (leaves.empty()) return samples;
  SeededRandom random(seed);
  const double turn = 2 * std::numbers::pi * random.Uniform();
  const double golden = std::numbers::pi * (3 - std::sqrt(5.0));
  for (int k = 0; k < count; ++k) {
    const double z = 1 - (2 * k + 1) / double(count);
    const double ring = std::sqrt(std::max(0.0, 1 - z * z)), phi = turn + golden * k;
    const Eigen::Vector3f d = Eigen::Vector3d(ring * std::cos(phi), ring * std::sin(phi), z).normalized().cast<float>();
    size_t best = 0;
    float reach = d.dot(leaves[0].centre);
    for (size_t i = 1; i < leaves.size(); ++i) {
      const float r = d.dot(leaves[i].centre);
      if (r > reach) reach = r, best = i;
    }
    samples.push_back({leaves[best].centre + static_cast<float>(radius) * d, d});
  }
  return samples;
}

}  // namespace voltree
