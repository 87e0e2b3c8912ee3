#include "compress/billboard_vectors.h"

#include <algorithm>
#include <cmath>

#include "compress/colour_space.h"
#include "core/error.h"

namespace voltree {
namespace {

uint8_t RoundToByte(float value) { return static_cast<uint8_t>(std::clamp(std::lround(value), 0L, 255L)); }

}  // namespace

ColourSpace ParseColourSpace(const std::string& name) {
  if (name == "lab") return ColourSpace::kLab;
  if (name == "rgb") return ColourSpace::kRgb;
  Fail("unknown colour space '", name, "'; expected lab or rgb");
}

std::string ColourSpaceName(ColourSpace space) { return space == ColourSpace::kLab ? "lab" : "rgb"; }

size_t CountBillboards(const Volume& volume) {
  size_t count = 0;
  for (const auto& level : volume.levels) count += level.billboards.size();
  return count;
}

std::vector<uint8_t> GatherTexels(const Volume& volume) {
  std::vector<uint8_t> texels;
  texels.reserve(CountBillboards(volume) * volume.BytesPerBillboard());
  for (size_t l = 0; l < volume.levels.size(); ++l) {
    const auto& level = volume.levels[l];
    if (level.texels.size() != level.billboards.size() * volume.BytesPerBillboard())
      Fail("volume level ", l, ": ", level.texels.size(), " texel bytes for ", level.billboards.size(),
           " billboards of ", volume.texels, "x", volume.texels, " RGBA8");
    texels.insert(texels.end(), level.texels.begin(), level.texels.end());
  }
  return texels;
}

TrainingSet ColourVectors(const std::vector<uint8_t>& texels, int texel_count, ColourSpace space, bool alpha_weighted) {
  const size_t count = texels.size() / (4 * size_t(texel_count));
  TrainingSet set;
  set.dimension = 3 * texel_count;
  set.vectors.resize(count * set.dimension);
  if (alpha_weighted) set.weights.resize(count * set.dimension);
  std::vector<float> straight(3 * texel_count);
  for (size_t b = 0; b < count; ++b) {
    const uint8_t* rgba = texels.data() + b * 4 * texel_count;
    // Un-premultiply in float: 8-bit straight colour would throw away the precision of faint texels.
    float mean[3] = {0, 0, 0}, alpha_sum = 0;
    for (int t = 0; t < texel_count; ++t) {
      const float a = rgba[4 * t + 3];
      for (int c = 0; c < 3; ++c) {
        straight[3 * t + c] = a > 0 ? std::min(1.f, rgba[4 * t + c] / a) : -1.f;
        mean[c] += rgba[4 * t + c] / 255.f;  // premultiplied sum = alpha-weighted straight sum
      }
      alpha_sum += a / 255.f;
    }
    for (int c = 0; c < 3; ++c) mean[c] = alpha_sum > 0 ? std::min(1.f, mean[c] / alpha_sum) : 0.5f;
    float* out = set.vectors.data() + b * set.dimension;
    for (int t = 0; t < texel_count; ++t) {
      float rgb[3];
      for (int c = 0; c < 3; ++c) rgb[c] = straight[3 * t] < 0 ? mean[c] : straight[3 * t + c];
      if (space == ColourSpace::kLab) {
        const Lab lab = SrgbToLab(rgb[0], rgb[1], rgb[2]);
        std::copy(lab.begin(), lab.end(), out + 3 * t);
      } else {
        for (int c = 0; c < 3; ++c) out[3 * t + c] = 255.f * rgb[c];
      }
      if (alpha_weighted)
        for (int c = 0; c < 3; ++c) set.weights[b * set.dimension + 3 * t + c] = rgba[4 * t + 3] / 255.f;
    }
  }
  return set;
}

TrainingSet AlphaVectors(const std::vector<uint8_t>& texels, int texel_count) {
  const size_t count = texels.size() / (4 * size_t(texel_count));
  TrainingSet set;
  set.dimension = texel_count;
  set.vectors.resize(count * texel_count);
  for (size_t i = 0; i < count * texel_count; ++i) set.vectors[i] = texels[4 * i + 3];
  return set;
}

std::vector<uint8_t> DecodeColourCodebook(const Codebook& codebook, ColourSpace space) {
  std::vector<uint8_t> rgb(codebook.codewords.size());
  for (size_t i = 0; i + 2 < codebook.codewords.size(); i += 3) {
    const float* v = codebook.codewords.data() + i;
    if (space == ColourSpace::kLab) {
      const auto bytes = LabToSrgb8({v[0], v[1], v[2]});
      std::copy(bytes.begin(), bytes.end(), rgb.begin() + i);
    } else {
      for (int c = 0; c < 3; ++c) rgb[i + c] = RoundToByte(v[c]);
    }
  }
  return rgb;
}

std::vector<uint8_t> DecodeAlphaCodebook(const Codebook& codebook) {
  std::vector<uint8_t> alpha(codebook.codewords.size());
  for (size_t i = 0; i < alpha.size(); ++i) alpha[i] = RoundToByte(codebook.codewords[i]);
  return alpha;
}

}  // namespace voltree
