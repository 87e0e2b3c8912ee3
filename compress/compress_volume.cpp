#include "compress/compress_volume.h"

#include <algorithm>
#include <limits>

#include "compress/atlas.h"
#include "compress/dxt5.h"
#include "compress/texture_psnr.h"
#include "core/error.h"
#include "core/volume_io.h"

namespace voltree {
namespace {

// What compression needs beyond a well-formed volume (core/volume_io.h): something to compress.
void CheckCompressible(const Volume& volume) {
  CheckVolume(volume, "volume");
  if (volume.levels.empty()) Fail("volume: no levels");
  if (CountBillboards(volume) == 0) Fail("volume: no billboards to compress (everything was pruned?)");
}

GlaOptions MakeGlaOptions(const CompressOptions& options, int codebook_size, CodewordRule rule, uint64_t seed) {
  GlaOptions gla;
  gla.codebook_size = codebook_size;
  gla.rule = rule;
  gla.tolerance = options.tolerance;
  gla.max_iterations = options.max_iterations;
  gla.seed = seed;
  return gla;
}

GlaObserver Reporter(Progress* progress, const std::string& what) {
  if (!progress) return {};
  return [progress, what](int iteration, double distortion) {
    progress->Say("compress", Str(what, " GLA iteration ", iteration + 1, ": mean distortion ", distortion));
  };
}

// Bounds of the kept cells of the finest level.
void CellBounds(const Volume& volume, Eigen::Vector3d& low, Eigen::Vector3d& high) {
  const int finest = int(volume.levels.size()) - 1;
  const auto& level = volume.levels[finest];
  const double s = volume.CellSize(finest);
  low = volume.origin + Eigen::Vector3d::Constant(volume.size);
  high = volume.origin;
  for (const auto& cell : level.cells) {
    const Eigen::Vector3d corner = volume.origin + s * Eigen::Vector3d(cell[0], cell[1], cell[2]);
    low = low.cwiseMin(corner);
    high = high.cwiseMax(corner + Eigen::Vector3d::Constant(s));
  }
  if (level.cells.empty()) low = high = volume.origin;
}

}  // namespace

void CompressOptions::Check() const {
  if (colour_codebook < 1 || colour_codebook > 65536)
    FailOption("CompressOptions.colour_codebook", "must be in 1..65536, got ", colour_codebook);
  if (alpha_codebook < 1 || alpha_codebook > 65536)
    FailOption("CompressOptions.alpha_codebook", "must be in 1..65536, got ", alpha_codebook);
  if (black_threshold < 0 || black_threshold > 255)
    FailOption("CompressOptions.black_threshold", "must be in 0..255, got ", black_threshold);
  if (!(tolerance >= 0 && tolerance < 1)) FailOption("CompressOptions.tolerance", "must be in [0, 1), got ", tolerance);
  if (max_iterations < 1) FailOption("CompressOptions.max_iterations", "must be at least 1, got ", max_iterations);
  if (smallest_budget_codebook < 1 || smallest_budget_codebook > 65536)
    FailOption("CompressOptions.smallest_budget_codebook", "must be in 1..65536, got ", smallest_budget_codebook);
  MakeGlaOptions(*this, colour_codebook, colour_rule, seed).Check();
}

nlohmann::json CompressOptions::ToJson() const {
  return {{"codebook", colour_codebook},
          {"alpha_codebook", alpha_codebook},
          {"space", ColourSpaceName(space)},
          {"gla", CodewordRuleName(colour_rule)},
          {"alpha_gla", CodewordRuleName(alpha_rule)},
          {"alpha_weighted", alpha_weighted},
          {"tolerance", tolerance},
          {"max_iterations", max_iterations},
          {"seed", seed},
          {"black_threshold", black_threshold}};
}

CompressOptions CompressOptions::FromJson(const nlohmann::json& recorded, const CompressOptions& absent) {
  const auto rule = [&recorded](const char* key, CodewordRule fallback) {
    try {
      return ParseCodewordRule(recorded.value(key, CodewordRuleName(fallback)));
    } catch (const Error& error) {
      Fail("the asset's provenance, options.", key, ": ", error.what());
    }
  };
  CompressOptions options = absent;
  options.colour_codebook = recorded.value("codebook", absent.colour_codebook);
  options.alpha_codebook = recorded.value("alpha_codebook", absent.alpha_codebook);
  options.space =
      recorded.value("space", ColourSpaceName(absent.space)) == "rgb" ? ColourSpace::kRgb : ColourSpace::kLab;
  options.colour_rule = rule("gla", absent.colour_rule);
  options.alpha_rule = rule("alpha_gla", options.colour_rule);
  options.alpha_weighted = recorded.value("alpha_weighted", absent.alpha_weighted);
  options.tolerance = recorded.value("tolerance", absent.tolerance);
  options.max_iterations = recorded.value("max_iterations", absent.max_iterations);
  options.seed = recorded.value("seed", absent.seed);
  options.black_threshold = recorded.value("black_threshold", absent.black_threshold);
  return options;
}

nlohmann::json CompressOptions::SettingsJson() const {
  nlohmann::json settings = ToJson();
  settings["zstd"] = zstd;
  settings["max_bytes"] = max_bytes;
  settings["smallest_budget_codebook"] = smallest_budget_codebook;
  settings["trade_codebooks"] = trade_codebooks;
  return settings;
}

std::vector<uint8_t> DecodeBillboardsFromCodewords(const std::vector<uint8_t>& colour_rgb,
                                                   const std::vector<uint8_t>& alpha_bytes, int texels,
                                                   const std::vector<CodewordUse>& uses) {
  const size_t n = size_t(texels) * texels;
  std::vector<uint8_t> out;
  out.reserve(uses.size() * n * 4);
  for (const CodewordUse& use : uses) {
    for (size_t t = 0; t < n; ++t) {
      const uint8_t* c = colour_rgb.data() + (use.colour * n + t) * 3;
      const uint8_t a = alpha_bytes[use.alpha * n + t];
      out.insert(out.end(), {Premultiply(c[0], a), Premultiply(c[1], a), Premultiply(c[2], a), a});
    }
  }
  return out;
}

std::vector<uint8_t> DecodeBillboardsFromAtlas(const VtreeAsset& asset) {
  const std::vector<uint8_t> decoded =
      DecodeDxt5(asset.atlas.dxt5.data(), int(asset.atlas.width), int(asset.atlas.height));
  std::vector<uint8_t> out;
  out.reserve(asset.BillboardCount() * asset.texels * asset.texels * 4);
  for (const auto& level : asset.levels)
    for (const auto& b : level.billboards) FetchBillboard(decoded, asset.atlas, asset.texels, b.colour, b.alpha, out);
  return out;
}

CompressResult CompressVolume(const Volume& volume, const CompressOptions& options, Progress* progress,
                              TrainedCodebooks* trained) {
  options.Check();
  CheckCompressible(volume);
  const int texel_count = volume.texels * volume.texels;
  const std::vector<uint8_t> texels = GatherTexels(volume);
  CompressResult result;
  CompressStats& stats = result.stats;
  stats.billboards = CountBillboards(volume);
  if (progress)
    progress->Say("compress", Str(stats.billboards, " billboards of ", volume.texels, "x", volume.texels, " texels"));

  // Distinct seeds per codebook so that colour and alpha do not share a random stream.
  TrainedCodebooks local;
  if (!trained) trained = &local;
  if (!trained->colour.contains(options.colour_codebook)) {
    if (!trained->colour_set)
      trained->colour_set = ColourVectors(texels, texel_count, options.space, options.alpha_weighted);
    trained->colour[options.colour_codebook] = RunGla(
        *trained->colour_set, MakeGlaOptions(options, options.colour_codebook, options.colour_rule, options.seed),
        Reporter(progress, "colour"));
  }
  if (!trained->alpha.contains(options.alpha_codebook)) {
    if (!trained->alpha_set) trained->alpha_set = AlphaVectors(texels, texel_count);
    trained->alpha[options.alpha_codebook] = RunGla(
        *trained->alpha_set,
        MakeGlaOptions(options, options.alpha_codebook, options.alpha_rule, options.seed ^ 0x9E3779B97F4A7C15ull),
        Reporter(progress, "alpha"));
  }
  stats.colour = trained->colour.at(options.colour_codebook);
  stats.alpha = trained->alpha.at(options.alpha_codebook);

  std::vector<CodewordUse> uses(stats.billboards);
  for (size_t i = 0; i < uses.size(); ++i)
    uses[i] = {uint16_t(stats.colour.assignment[i]), uint16_t(stats.alpha.assignment[i])};
  stats.colour_rgb = DecodeColourCodebook(stats.colour.codebook, options.space);
  stats.alpha_bytes = DecodeAlphaCodebook(stats.alpha.codebook);
  stats.black_texels_fixed =
      FixBlackTexels(stats.colour_rgb, stats.alpha_bytes, texel_count, uses, options.black_threshold);
  stats.psnr_vq = Psnr(texels, DecodeBillboardsFromCodewords(stats.colour_rgb, stats.alpha_bytes, volume.texels, uses));

  VtreeAsset& asset = result.asset;
  asset.origin = volume.origin;
  asset.size = volume.size;
  asset.branching = volume.branching;
  asset.texels = volume.texels;
  CellBounds(volume, asset.bounds_min, asset.bounds_max);
  for (const auto& view : volume.views) asset.views.push_back({view.name, view.position, view.direction, view.up});
  size_t next = 0;
  for (const auto& level : volume.levels) {
    VtreeLevel out;
    out.resolution = static_cast<uint32_t>(level.resolution);
    out.cells = level.cells;
    out.density = level.density;
    out.billboards_before_pruning = level.billboards_before_pruning;
    for (const auto& b : level.billboards) {
      out.billboards.push_back({b.cell, b.view, uses[next].colour, uses[next].alpha});
      ++next;
    }
    asset.levels.push_back(std::move(out));
  }
  asset.colour_codebook_size = static_cast<uint32_t>(stats.colour.codebook.size());
  asset.alpha_codebook_size = static_cast<uint32_t>(stats.alpha.codebook.size());
  asset.colour_space = ColourSpaceName(options.space);
  if (progress) progress->Say("compress", "DXT5 atlas (libsquish cluster fit)");
  asset.atlas = BuildAtlas(stats.colour_rgb, stats.alpha_bytes, volume.texels);
  asset.provenance = {{"tool", "voltree 0.1.0"}, {"options", options.ToJson()}};
  stats.psnr_dxt5 = Psnr(texels, DecodeBillboardsFromAtlas(asset));
  if (progress)
    progress->Say("compress", Str("texture PSNR ", stats.psnr_vq, " dB after VQ, ", stats.psnr_dxt5, " dB after DXT5; ",
                                  stats.black_texels_fixed, " black texels fixed"));
  return result;
}

}  // namespace voltree
