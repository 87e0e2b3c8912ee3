// The compress stage: Volume (reconstruct/) -> VtreeAsset (core/vtree.h).
// Colour and alpha codebooks by GLA, black-texel fix, DXT5 codebook atlas, billboard records.
#pragma once

#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "compress/billboard_vectors.h"
#include "compress/black_texels.h"
#include "compress/gla.h"
#include "compress/trained_codebooks.h"
#include "core/progress.h"
#include "core/vtree.h"
#include "core/volume.h"

namespace voltree {

struct CompressOptions {
  // The largest codebooks tried under max_bytes (compress/byte_budget.h). Linz 2006 uses 512
  // (1024 for a low-contrast tree); a sparse tree fits 2048 in 1 MiB, and its input views show it.
  int colour_codebook = 2048;
  int alpha_codebook = 2048;
  ColourSpace space = ColourSpace::kLab;
  // The codeword rule of each codebook. Linz 2006 keeps the member closest to the centroid for
  // both; measured, colour is better served by the centroid itself (README: Compress, the codeword
  // rule), alpha by the member, whose crisp 0 and 1 the over operator composites truer.
  CodewordRule colour_rule = CodewordRule::kCentroid;
  CodewordRule alpha_rule = CodewordRule::kClosestMember;
  // Weight colour distances by texel alpha: the texels a billboard does not draw do not steer its
  // codeword (+0.43 to +0.46 dB RGB at the input views of the four trees measured).
  bool alpha_weighted = true;
  double tolerance = 1e-3;
  int max_iterations = 40;
  uint64_t seed = 1;
  int black_threshold = 4;  // a quantized texel with all channels <= this is "black"
  // The file, which CompressVolume ignores: chunks zstd-compressed (the web page reads raw ones),
  // and a budget in bytes (0: none) that the codebooks are halved to fit, not below the smallest.
  bool zstd = true;
  uint64_t max_bytes = uint64_t(1) << 20;
  int smallest_budget_codebook = 64;
  // When the budget binds, colour codewords may be traded for alpha ones where the texture PSNR
  // gains (compress/byte_budget.h).
  bool trade_codebooks = true;

  void Check() const;
  nlohmann::json ToJson() const;  // for the asset's provenance: what shapes its content, not the file
  // The options ToJson() recorded. A key an older release did not record keeps `absent`'s value,
  // and a missing "alpha_gla" the recorded "gla" (one rule served both codebooks then).
  static CompressOptions FromJson(const nlohmann::json& recorded, const CompressOptions& absent);
  nlohmann::json SettingsJson() const;  // ToJson() and the file's settings: what run's recipe and demo.json record
};

struct CompressStats {
  size_t billboards = 0;
  GlaResult colour;  // codebook, assignment, distortion history
  GlaResult alpha;
  size_t black_texels_fixed = 0;
  double psnr_vq = 0;                // billboards rebuilt from the 8-bit codewords
  double psnr_dxt5 = 0;              // billboards as the renderer fetches them from the DXT5 atlas
  std::vector<uint8_t> colour_rgb;   // decoded codewords after the black fix, K x n*n x 3
  std::vector<uint8_t> alpha_bytes;  // decoded alpha codewords, K x n*n
};

struct CompressResult {
  VtreeAsset asset;
  CompressStats stats;
};

// `trained` (or none) holds codebooks already trained on this volume with these options but for
// the sizes; the sizes it lacks are trained and added.
CompressResult CompressVolume(const Volume& volume, const CompressOptions& options, Progress* progress = nullptr,
                              TrainedCodebooks* trained = nullptr);

// Billboards rebuilt from codewords (premultiplied RGBA8), in GatherTexels order.
std::vector<uint8_t> DecodeBillboardsFromCodewords(const std::vector<uint8_t>& colour_rgb,
                                                   const std::vector<uint8_t>& alpha_bytes, int texels,
                                                   const std::vector<CodewordUse>& uses);
// Billboards as fetched from the asset's DXT5 atlas (decoded with our reference decoder).
std::vector<uint8_t> DecodeBillboardsFromAtlas(const VtreeAsset& asset);

}  // namespace voltree
