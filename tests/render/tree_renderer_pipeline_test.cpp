// End to end: a tiny synthetic capture (8 views at 96x96, 4 levels) through the real `voltree`
// synth -> reconstruct -> compress, then rendered from its own input cameras: the renders must
// reproduce the photos' mattes. About 2 s; skipped when the voltree binary is not built.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <unistd.h>

#include "core/colmap_model.h"
#include "core/image.h"
#include "core/image_metrics.h"
#include "core/vtree.h"
#include "render/gl_context.h"
#include "render/tree_renderer.h"

namespace voltree {
namespace {

namespace fs = std::filesystem;

Image8 MatteAsRgba(const Image8& matte) {
  Image8 rgba(matte.width, matte.height, 4, 255);
  for (int y = 0; y < matte.height; ++y)
    for (int x = 0; x < matte.width; ++x) rgba.at(x, y, 3) = matte.at(x, y);
  return rgba;
}

TEST(TreeRendererPipeline, InputCamerasReproduceTheMattes) {
  if (!fs::exists(VOLTREE_BINARY)) GTEST_SKIP() << "build the voltree target first: " << VOLTREE_BINARY;
  const fs::path dir = fs::temp_directory_path() / ("voltree_render_pipeline_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  const std::string b = VOLTREE_BINARY, d = dir.string();
  ASSERT_EQ(std::system((b + " synth --tree oak --views 8 --size 96x96 --quiet -o " + d + " && " + b + " reconstruct " +
                         d + " --levels 4 --quiet && " + b + " compress " + d + " --quiet")
                            .c_str()),
            0);
  const VtreeAsset asset = ReadAsset(dir / "tree.vtree");
  const std::vector<View> views = ReadColmapText(dir / "sparse").Views();
  ASSERT_EQ(views.size(), 8u);
  GlContext context;
  TreeRenderer renderer(asset);
  double psnr = 0, precision = 0, recall = 0, mismatched_psnr = 0;
  std::vector<Image8> mattes, renders;
  for (const View& view : views) {
    renders.push_back(renderer.Render(view, {}));
    mattes.push_back(MatteAsRgba(ReadImage8(dir / "mattes" / fs::path(view.name).replace_extension(".png"), 1)));
  }
  for (size_t i = 0; i < views.size(); ++i) {
    const ViewMetrics own = CompareViews(renders[i], mattes[i]);
    psnr += own.alpha_psnr / 8, precision += own.precision / 8, recall += own.recall / 8;
    // Control: the same render against the next view's matte.
    mismatched_psnr += CompareViews(renders[i], mattes[(i + 1) % 8]).alpha_psnr / 8;
  }
  fs::remove_all(dir);
  // Measured (llvmpipe, seed 1): alpha PSNR 20.98 dB (worst view 20.12), precision 0.935,
  // recall 0.918 (reconstruction + VQ + DXT5 limit this, not the renderer: the hand-built
  // asset of tree_renderer_test is reproduced exactly); against the wrong matte PSNR is ~13 dB.
  EXPECT_GT(psnr, 19.5);
  EXPECT_GT(precision, 0.88);
  EXPECT_GT(recall, 0.86);
  EXPECT_GT(psnr - mismatched_psnr, 4.0) << "own " << psnr << " dB, mismatched " << mismatched_psnr << " dB";
  std::printf("alpha PSNR %.2f dB (mismatched %.2f), precision %.3f, recall %.3f\n", psnr, mismatched_psnr, precision,
              recall);
}

}  // namespace
}  // namespace voltree
