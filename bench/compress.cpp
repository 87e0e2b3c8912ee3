// Compression benchmark (Linz 2006 Fig. 6 and section 6): texture PSNR vs codebook size for four
// GLA variants, bytes by category, and GLA speed against OpenCV's cv::kmeans.
//   voltree-bench-compress [--volume DIR/volume] [--billboards N] [--sizes 64,128,...] [--iterations N]
//                          [--speed-only] [--repeats N]
// Without --volume it uses a synthetic volume (compress/synthetic_volume.h) and says so.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <ctime>
#include <opencv2/core.hpp>
#include <string>
#include <vector>

#include "compress/asset_accounting.h"
#include "compress/atlas.h"
#include "compress/billboard_vectors.h"
#include "compress/black_texels.h"
#include "compress/compress_volume.h"
#include "compress/dxt5.h"
#include "compress/gla.h"
#include "compress/synthetic_volume.h"
#include "compress/texture_psnr.h"
#include "core/error.h"
#include "core/volume_io.h"

using namespace voltree;

namespace {

double Seconds(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

struct Variant {
  const char* name;
  ColourSpace space;
  CodewordRule rule;
  bool weighted;
};

struct Quality {
  double psnr_vq = 0, psnr_dxt5 = 0, seconds = 0;
  int iterations = 0;
};

Quality Measure(const std::vector<uint8_t>& texels, int n, const Variant& variant, int size, const GlaResult& alpha,
                const std::vector<uint8_t>& alpha_bytes, int iterations) {
  const int texel_count = n * n;
  const TrainingSet set = ColourVectors(texels, texel_count, variant.space, variant.weighted);
  GlaOptions options;
  options.codebook_size = size;
  options.rule = variant.rule;
  options.max_iterations = iterations;
  const auto start = std::chrono::steady_clock::now();
  const GlaResult colour = RunGla(set, options);
  Quality quality;
  quality.seconds = Seconds(start);
  quality.iterations = colour.iterations;
  std::vector<uint8_t> rgb = DecodeColourCodebook(colour.codebook, variant.space);
  std::vector<CodewordUse> uses(colour.assignment.size());
  for (size_t i = 0; i < uses.size(); ++i) uses[i] = {uint16_t(colour.assignment[i]), uint16_t(alpha.assignment[i])};
  FixBlackTexels(rgb, alpha_bytes, texel_count, uses, 4);
  quality.psnr_vq = Psnr(texels, DecodeBillboardsFromCodewords(rgb, alpha_bytes, n, uses));
  const VtreeAtlas atlas = BuildAtlas(rgb, alpha_bytes, n);
  const std::vector<uint8_t> decoded = DecodeDxt5(atlas.dxt5.data(), int(atlas.width), int(atlas.height));
  std::vector<uint8_t> fetched;
  for (const auto& use : uses) FetchBillboard(decoded, atlas, n, use.colour, use.alpha, fetched);
  quality.psnr_dxt5 = Psnr(texels, fetched);
  return quality;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"voltree compression benchmark"};
  std::string volume_dir;
  int billboards = 20000, iterations = 20, kmeans_iterations = 10, repeats = 3;
  std::vector<int> sizes = {64, 128, 256, 512, 1024, 2048, 4096};
  app.add_option("--volume", volume_dir, "A reconstruction folder (DIR/volume); default: a synthetic volume");
  app.add_option("--billboards", billboards, "Synthetic volume size")->capture_default_str();
  app.add_option("--sizes", sizes, "Codebook sizes")->delimiter(',');
  app.add_option("--iterations", iterations, "Max GLA iterations for the PSNR table")->capture_default_str();
  app.add_option("--kmeans-iterations", kmeans_iterations, "Iterations for the cv::kmeans comparison")
      ->capture_default_str();
  app.add_option("--repeats", repeats, "Runs of each side in the cv::kmeans comparison; the best is reported")
      ->capture_default_str()
      ->check(CLI::Range(1, 100));
  bool speed_only = false;
  app.add_flag("--speed-only", speed_only, "Only the GLA vs cv::kmeans timing (skip the PSNR table and the bytes)");
  CLI11_PARSE(app, argc, argv);
  try {
    Volume volume;
    if (volume_dir.empty()) {
      SyntheticVolumeOptions options;
      options.billboards = billboards;
      options.levels = 6;
      volume = MakeSyntheticVolume(options);
      std::printf("input: SYNTHETIC volume (compress/synthetic_volume.cpp), %d requested billboards\n", billboards);
    } else {
      volume = ReadVolume(volume_dir);
      std::printf("input: reconstructed volume %s\n", volume_dir.c_str());
    }
    const std::vector<uint8_t> texels = GatherTexels(volume);
    const int n = volume.texels, texel_count = n * n;
    std::printf("%zu billboards of %dx%d texels, %zu levels\n\n", CountBillboards(volume), n, n, volume.levels.size());

    if (!speed_only) {  // 1. and 2.
      // 1. PSNR vs codebook size.
      const std::vector<Variant> variants = {{"RGB-GLA", ColourSpace::kRgb, CodewordRule::kCentroid, false},
                                             {"Lab-GLA", ColourSpace::kLab, CodewordRule::kCentroid, false},
                                             {"Lab-modified", ColourSpace::kLab, CodewordRule::kClosestMember, false},
                                             {"Lab-mod-alphaw", ColourSpace::kLab, CodewordRule::kClosestMember, true},
                                             {"Lab-GLA-alphaw", ColourSpace::kLab, CodewordRule::kCentroid, true}};
      std::printf("Texture PSNR (dB, premultiplied RGBA8 over all billboards; alpha codebook = colour size)\n");
      std::printf("VQ = 8-bit codewords, DXT5 = fetched from the DXT5 atlas\n");
      std::printf("%8s", "size");
      for (const auto& v : variants) std::printf("  %16s", v.name);
      std::printf("  %10s\n", "seconds");
      const TrainingSet alpha_set = AlphaVectors(texels, texel_count);
      for (int size : sizes) {
        GlaOptions alpha_options;
        alpha_options.codebook_size = size;
        alpha_options.max_iterations = iterations;
        const GlaResult alpha = RunGla(alpha_set, alpha_options);
        const std::vector<uint8_t> alpha_bytes = DecodeAlphaCodebook(alpha.codebook);
        std::printf("%8d", size);
        double seconds = 0;
        for (const auto& v : variants) {
          const Quality q = Measure(texels, n, v, size, alpha, alpha_bytes, iterations);
          std::printf("  %7.2f / %6.2f", q.psnr_vq, q.psnr_dxt5);
          seconds += q.seconds;
          std::fflush(stdout);
        }
        std::printf("  %10.1f\n", seconds);
      }

      // 2. Bytes at the default settings.
      CompressOptions defaults;
      const auto start = std::chrono::steady_clock::now();
      const CompressResult result = CompressVolume(volume, defaults);
      const double compress_seconds = Seconds(start);
      VtreeWriteOptions zstd;
      zstd.zstd = true;
      const uint64_t raw_file = SerializeAsset(result.asset).size();
      const uint64_t zstd_file = SerializeAsset(result.asset, zstd).size();
      const AssetBytes bytes = CountAssetBytes(result.asset, raw_file);
      std::printf(
          "\nDefault compress (codebook %d / %d, %s, %s colour GLA, %s alpha GLA%s): %.1f s, PSNR %.2f dB VQ, %.2f dB "
          "DXT5\n",
          defaults.colour_codebook, defaults.alpha_codebook, defaults.space == ColourSpace::kLab ? "lab" : "rgb",
          CodewordRuleName(defaults.colour_rule).c_str(), CodewordRuleName(defaults.alpha_rule).c_str(),
          defaults.alpha_weighted ? ", alpha-weighted" : "", compress_seconds, result.stats.psnr_vq,
          result.stats.psnr_dxt5);
      std::printf("%s", DescribeAsset(result.asset, bytes).c_str());
      std::printf("  on disk with --zstd          %llu bytes\n", static_cast<unsigned long long>(zstd_file));
      std::printf(
          "  ratio uncompressed -> GPU textures: %.1f:1 (atlas only); %.1f:1 counting the index pairs (as narrow as "
          "the codebooks allow)\n",
          double(bytes.uncompressed_textures) / double(bytes.GpuTextures()),
          double(bytes.uncompressed_textures) / double(bytes.gpu_atlas + bytes.vq_indices));
    }

    // 3. GLA vs cv::kmeans, same vectors, same initialization rule (k-means++), same iterations.
    const TrainingSet set = ColourVectors(texels, texel_count, ColourSpace::kLab, false);
    const int k = 512;
    GlaOptions options;
    options.codebook_size = k;
    options.rule = CodewordRule::kCentroid;
    options.tolerance = 0;
    options.max_iterations = kmeans_iterations;
    // Wall time and process CPU time, the best of `repeats` runs taken in turns, so both sides
    // see the same machine: on a shared machine single runs vary by 20 %.
    struct Timing {
      double wall = 1e30, cpu = 1e30;
      void Add(std::chrono::steady_clock::time_point start, std::clock_t clock) {
        wall = std::min(wall, Seconds(start));
        cpu = std::min(cpu, double(std::clock() - clock) / CLOCKS_PER_SEC);
      }
    } ours_time, cv_time;
    GlaResult ours;
    double cv_lowest = 1e30, cv_highest = 0;  // OpenCV's RNG, so its seeding, differs from run to run
    cv::Mat data(int(set.size()), set.dimension, CV_32F, const_cast<float*>(set.vectors.data()));
    for (int run = 0; run < repeats; ++run) {
      auto t0 = std::chrono::steady_clock::now();
      std::clock_t c0 = std::clock();
      ours = RunGla(set, options);
      ours_time.Add(t0, c0);
      cv::Mat labels, centres;
      t0 = std::chrono::steady_clock::now();
      c0 = std::clock();
      const double compactness =
          cv::kmeans(data, k, labels, cv::TermCriteria(cv::TermCriteria::MAX_ITER, kmeans_iterations, 0), 1,
                     cv::KMEANS_PP_CENTERS, centres);
      cv_time.Add(t0, c0);
      cv_lowest = std::min(cv_lowest, compactness / double(set.size()));
      cv_highest = std::max(cv_highest, compactness / double(set.size()));
    }
    std::printf(
        "\nGLA vs cv::kmeans (k = %d, %zu vectors of %d dims, %d iterations, %d threads available,"
        " best of %d runs)\n",
        k, set.size(), set.dimension, kmeans_iterations, cv::getNumThreads(), repeats);
    std::printf("%12s  %10s  %10s  %18s\n", "", "wall s", "CPU s", "mean distortion");
    std::printf("%12s  %10.2f  %10.2f  %18.3f\n", "voltree GLA", ours_time.wall, ours_time.cpu, ours.distortion);
    std::printf("%12s  %10.2f  %10.2f  %8.3f..%.3f\n", "cv::kmeans", cv_time.wall, cv_time.cpu, cv_lowest, cv_highest);
    std::printf("speed-up %.2fx wall, %.2fx CPU\n", cv_time.wall / ours_time.wall, cv_time.cpu / ours_time.cpu);
    // Where GLA's time goes: k-means++ seeding against the Lloyd iterations.
    auto t0 = std::chrono::steady_clock::now();
    Codebook seeded = SeedKMeansPlusPlus(set, size_t(k), options.seed, options.seeding_trials).centres;
    const double seeding_seconds = Seconds(t0);
    t0 = std::chrono::steady_clock::now();
    RunGlaFrom(set, options, std::move(seeded));
    std::printf("voltree GLA: k-means++ seeding %.2f s, %d Lloyd iterations %.2f s (wall)\n", seeding_seconds,
                kmeans_iterations, Seconds(t0));
  } catch (const Error& error) {
    std::fprintf(stderr, "error: %s\n", error.what());
    return 1;
  }
  return 0;
}
