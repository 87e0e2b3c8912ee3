#include "compress/asset_accounting.h"

#include <gtest/gtest.h>

namespace voltree {
namespace {

// The GPU holds the atlas, 4 bytes of alpha extent per tile and at most one 16-byte record per
// leaf cell; nothing per billboard, so more billboards cost the GPU nothing.
TEST(AssetAccounting, GpuBytesAreTheAtlasTheExtentsAndOneRecordPerLeafCell) {
  VtreeAsset asset;
  asset.texels = 4;
  asset.levels.resize(2);
  asset.levels[0].resolution = 1, asset.levels[0].cells = {{0, 0, 0}};
  asset.levels[1].resolution = 2, asset.levels[1].cells = {{0, 0, 0}, {1, 0, 1}, {1, 1, 1}};
  asset.levels[1].billboards = {{0, 0, 3, 1}, {0, 1, 2, 1}, {1, 0, 0, 0}, {2, 1, 1, 2}};
  asset.colour_codebook_size = 4, asset.alpha_codebook_size = 3;
  asset.atlas.tile_count = 4;
  asset.atlas.dxt5.assign(4 * 16, 0);
  const AssetBytes bytes = CountAssetBytes(asset, 1234);
  EXPECT_EQ(bytes.gpu_atlas, 64u);
  EXPECT_EQ(bytes.gpu_alpha_extents, 16u);
  EXPECT_EQ(bytes.gpu_frame_records, 3u * 16);
  EXPECT_EQ(bytes.Gpu(), 64u + 16 + 48);
  EXPECT_EQ(bytes.uncompressed_textures, 4u * 16 * 4);
  EXPECT_EQ(bytes.vq_indices, 2u);  // 4 billboards x (2 + 2) bits
  EXPECT_NE(DescribeAsset(asset, bytes).find("3 leaf cells"), std::string::npos) << DescribeAsset(asset, bytes);

  asset.levels[1].billboards.push_back({2, 2, 3, 2});
  EXPECT_EQ(CountAssetBytes(asset).Gpu(), bytes.Gpu());
}

}  // namespace
}  // namespace voltree
