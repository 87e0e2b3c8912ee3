// `voltree view` in a real window: Xvfb gives GLFW an X display with Mesa's OpenGL, a script
// drives the session (a drag, screenshots, the level tint), and each screenshot is compared with
// `voltree render` from the camera saved beside it: RGB PSNR >= 35 dB over the same grey. The tint
// and nearest-view toggles must change the image, and without a display (or with too old an
// OpenGL) the command names `render`. About 15 s.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <regex>
#include <string>
#include <vector>

#include "core/files.h"
#include "core/image.h"
#include "core/image_metrics.h"
#include "pipeline/voltree_binary.h"
#include "tiny_asset_suite.h"

namespace voltree {
namespace {

namespace fs = std::filesystem;

constexpr double kMinPsnrAgainstRender = 35;

// xvfb-run with a display number of this process's own: `-a` alone picks the first free number,
// and two tests starting at once (ctest -j) can both pick it. The X authority file is ours too:
// the temporary folder xvfb-run makes for it otherwise sometimes fails to be removed on a loaded
// machine, and xvfb-run then exits 5 whatever the command returned.
std::string XvfbRun(const fs::path& dir) {
  return "timeout 120 xvfb-run -a -n " + std::to_string(100 + ::getpid() % 800) + " -f '" +
         (dir / "xauthority").string() + "' -s '-screen 0 640x480x24' ";
}

class ViewWindow : public test::TinyAssetSuite {
 protected:
  static void SetUpTestSuite() { BuildTinyAsset("voltree_view_"); }
  void SetUp() override { RequireToolAndAsset("xvfb-run", "xvfb"); }

  // Runs `voltree view INPUT OPTIONS` under Xvfb with `script`, screenshots into Dir()/NAME.
  static test::Outcome View(const std::string& input, const std::string& script, const std::string& name,
                            const std::string& options = "") {
    WriteFileAtomic(Dir() / (name + ".txt"), script);
    return test::VoltreeCaptured("view '" + input + "' --size 256x256 --script '" + (Dir() / (name + ".txt")).string() +
                                     "' -o '" + (Dir() / name).string() + "' " + options,
                                 "", XvfbRun(Dir()));
  }

  // `voltree render` from a screenshot's saved camera, over the viewer's grey, with `options`.
  static Image8 RenderSaved(const std::string& input, const fs::path& camera_model, const std::string& name,
                            const std::string& options = "") {
    const fs::path frames = Dir() / ("render_" + name);
    const test::Outcome outcome =
        test::VoltreeCaptured("render '" + input + "' --cameras '" + camera_model.string() +
                              "' --background 128,128,128 --quiet " + options + " -o '" + frames.string() + "'");
    EXPECT_EQ(outcome.status, 0) << outcome.output;
    return ReadImage8(frames / (camera_model.filename().string() + ".png"), 4);
  }

  static double Psnr(const Image8& a, const Image8& b) {
    if (a.width != b.width || a.height != b.height) {
      ADD_FAILURE() << "sizes differ: " << a.width << "x" << a.height << " and " << b.width << "x" << b.height;
      return 0;
    }
    return CompareViews(a, b).rgb_psnr;
  }
};

TEST_F(ViewWindow, ScreenshotMatchesRenderAndTintChangesIt) {
  const test::Outcome outcome = View(Asset().string(),
                                     "0.1 drag 60 -15\n"
                                     "0.2 scroll 2\n"
                                     "0.3 screenshot\n"
                                     "0.4 key T\n"
                                     "0.5 screenshot\n"
                                     "0.6 key T\n"
                                     "0.6 key V\n"
                                     "0.7 screenshot\n"
                                     "0.8 quit\n",
                                     "asset");
  ASSERT_EQ(outcome.status, 0) << outcome.output;
  EXPECT_NE(outcome.output.find("3 screenshots"), std::string::npos) << outcome.output;
  const fs::path shots = Dir() / "asset";
  const Image8 plain = ReadImage8(shots / "view_000.png", 4), tinted = ReadImage8(shots / "view_001.png", 4);
  const double psnr = Psnr(plain, RenderSaved(Asset().string(), shots / "view_000", "plain"));
  const double tinted_psnr = Psnr(tinted, RenderSaved(Asset().string(), shots / "view_001", "tinted"));
  std::printf("window vs render from the saved camera: %.2f dB; tinted window vs untinted render: %.2f dB\n", psnr,
              tinted_psnr);
  EXPECT_GE(psnr, kMinPsnrAgainstRender);
  EXPECT_LT(Psnr(plain, tinted), 30) << "the level tint did not change the image";
  EXPECT_LT(tinted_psnr, 30) << "render draws no tint, the tinted window must differ from it";
  EXPECT_LT(Psnr(plain, Image8(256, 256, 4, 128)), kMinPsnrAgainstRender - 10)
      << "the window shows nothing but the background";
  // V: the nearest input view alone, not the two-view blend.
  const double nearest = Psnr(ReadImage8(shots / "view_002.png", 4), plain);
  std::printf("nearest view alone vs the blend: %.2f dB\n", nearest);
  EXPECT_LT(nearest, 40) << "V did not change the image";
}

// The other toggles each match `render` with the option they stand for, from the saved camera:
// a forced level (key 1, tinted: --level 1 --tint-levels) and the planes LOD rule (L: --lod
// planes). R after a drag and a pan gives back the first view; the pan and zoom move it.
TEST_F(ViewWindow, TogglesMatchRenderOptionsAndResetReturns) {
  const std::string script =
      "0.1 screenshot\n0.2 drag 45 10\n0.2 pan 30 -20\n0.2 scroll 3\n0.3 screenshot\n"  // start; moved
      "0.4 key R\n0.5 screenshot\n"                                                     // reset
      "0.6 key 1\n0.6 key T\n0.7 screenshot\n"                                          // level 1, tinted
      "0.8 key 1\n0.8 key T\n0.8 scroll 4\n0.8 key L\n0.9 screenshot\n1.0 quit\n";      // planes, closer
  const test::Outcome outcome = View(Asset().string(), script, "toggles");
  ASSERT_EQ(outcome.status, 0) << outcome.output;
  EXPECT_NE(outcome.output.find("5 screenshots"), std::string::npos) << outcome.output;
  const fs::path shots = Dir() / "toggles";
  const auto shot = [&](int i) { return ReadImage8(shots / ("view_00" + std::to_string(i) + ".png"), 4); };
  const double moved = Psnr(shot(0), shot(1)), reset = Psnr(shot(0), shot(2));
  const double level =
      Psnr(shot(3), RenderSaved(Asset().string(), shots / "view_003", "level", "--level 1 --tint-levels"));
  const double level_auto =
      Psnr(shot(3), RenderSaved(Asset().string(), shots / "view_003", "level_auto", "--tint-levels"));
  const double planes = Psnr(shot(4), RenderSaved(Asset().string(), shots / "view_004", "planes", "--lod planes"));
  std::printf(
      "drag, pan and zoom vs start %.2f dB; after R %.2f dB; key 1 vs render --level 1 %.2f dB (vs automatic "
      "LOD %.2f dB); L vs render --lod planes %.2f dB\n",
      moved, reset, level, level_auto, planes);
  EXPECT_LT(moved, 30) << "drag, pan and zoom did not move the view";
  EXPECT_GE(reset, 60) << "R did not give back the first view";
  EXPECT_GE(level, kMinPsnrAgainstRender);
  EXPECT_LT(level_auto, level - 3) << "the forced level looks like the automatic LOD";
  EXPECT_GE(planes, kMinPsnrAgainstRender);
  EXPECT_NE(outcome.output.find("view_004.png (camera: " + (shots / "view_004").string()), std::string::npos);
  EXPECT_NE(outcome.output.find("billboards drawn; LOD planes;"), std::string::npos) << "L did not switch the rule";
  EXPECT_EQ(outcome.output.find("LOD planes"), outcome.output.rfind("LOD planes")) << outcome.output;
}

// The billboards drawn, as the viewer prints them after each screenshot's name.
std::vector<long> BillboardsDrawn(const std::string& output) {
  std::vector<long> drawn;
  const std::regex pattern("; ([0-9]+) billboards drawn;");
  for (auto it = std::sregex_iterator(output.begin(), output.end(), pattern); it != std::sregex_iterator(); ++it)
    drawn.push_back(std::stol((*it)[1]));
  return drawn;
}

// U draws the --unpruned asset (the same capture reconstructed with --prune 1): more billboards,
// and the image `render` draws of that asset.
TEST_F(ViewWindow, PruningOffDrawsTheUnprunedAsset) {
  const fs::path capture = Dir() / "unpruned_capture";
  fs::remove_all(capture);
  fs::copy(Dir() / "capture", capture, fs::copy_options::recursive);
  fs::remove_all(capture / "volume");
  fs::remove(capture / "tree.vtree");
  ASSERT_EQ(test::Voltree("reconstruct '" + capture.string() + "' --levels 4 --prune 1 --quiet && " + VOLTREE_BINARY +
                          " compress '" + capture.string() + "' --quiet"),
            0);
  const fs::path unpruned = capture / "tree.vtree";
  const test::Outcome outcome =
      View(Asset().string(), "0.1 drag 30 -10\n0.2 screenshot\n0.3 key U\n0.4 screenshot\n0.5 quit\n", "prune",
           "--unpruned '" + unpruned.string() + "'");
  ASSERT_EQ(outcome.status, 0) << outcome.output;
  EXPECT_NE(outcome.output.find("pruning on (U): "), std::string::npos) << outcome.output;
  EXPECT_NE(outcome.output.find("pruning off (U): "), std::string::npos) << outcome.output;
  const std::vector<long> drawn = BillboardsDrawn(outcome.output);
  ASSERT_EQ(drawn.size(), 2u) << outcome.output;
  EXPECT_GT(drawn[1], drawn[0]) << "pruning off must draw the billboards pruning took out";
  const fs::path shots = Dir() / "prune";
  const Image8 on = ReadImage8(shots / "view_000.png", 4), off = ReadImage8(shots / "view_001.png", 4);
  const double psnr = Psnr(off, RenderSaved(unpruned.string(), shots / "view_001", "unpruned"));
  std::printf(
      "pruning off: %ld billboards drawn (on: %ld); window vs render of the unpruned asset %.2f dB; pruning "
      "on vs off %.2f dB\n",
      drawn[1], drawn[0], psnr, Psnr(on, off));
  EXPECT_GE(psnr, kMinPsnrAgainstRender);
}

TEST_F(ViewWindow, SceneFlownThroughMatchesRender) {
  const fs::path scene = Dir() / "capture" / "three.json";
  WriteFileAtomic(scene, R"({
  "assets": {"oak": "tree.vtree"},
  "ground": {"size": 60},
  "instances": [
    {"asset": "oak", "position": [-9, 0, 0]},
    {"asset": "oak", "position": [6, 7, 0], "rotation": 120, "scale": 0.8},
    {"asset": "oak", "position": [4, -8, 0], "rotation": 250, "scale": 1.2}
  ]
})");
  const test::Outcome outcome =
      View(scene.string(), "0.1 key W\n0.2 key W\n0.3 key D\n0.4 drag -30 10\n0.5 screenshot\n0.6 quit\n", "scene");
  ASSERT_EQ(outcome.status, 0) << outcome.output;
  const Image8 shot = ReadImage8(Dir() / "scene" / "view_000.png", 4);
  const double psnr = Psnr(shot, RenderSaved(scene.string(), Dir() / "scene" / "view_000", "scene"));
  std::printf("scene window vs render: %.2f dB\n", psnr);
  EXPECT_GE(psnr, kMinPsnrAgainstRender);
}

TEST_F(ViewWindow, WithoutADisplayNamesRender) {
  const test::Outcome outcome =
      test::VoltreeCaptured("view '" + Asset().string() + "'", "", "env -u DISPLAY -u WAYLAND_DISPLAY ");
  EXPECT_EQ(outcome.status, 1) << outcome.output;
  EXPECT_NE(outcome.output.find("no display"), std::string::npos) << outcome.output;
  EXPECT_NE(outcome.output.find("voltree render"), std::string::npos) << outcome.output;
}

// Mesa told to offer OpenGL 3.3 stands for an old driver: the message says what is needed.
TEST_F(ViewWindow, TooOldOpenGlIsNamed) {
  const test::Outcome outcome =
      test::VoltreeCaptured("view '" + Asset().string() + "'", "", "MESA_GL_VERSION_OVERRIDE=3.3 " + XvfbRun(Dir()));
  EXPECT_EQ(outcome.status, 1) << outcome.output;
  EXPECT_NE(outcome.output.find("no OpenGL 4.3 core profile"), std::string::npos) << outcome.output;
  EXPECT_NE(outcome.output.find("voltree render"), std::string::npos) << outcome.output;
}

TEST_F(ViewWindow, BadScriptLineIsNamed) {
  WriteFileAtomic(Dir() / "bad.txt", "0.1 drag 10 10\n0.2 jump 3\n");
  const test::Outcome outcome =
      test::VoltreeCaptured("view '" + Asset().string() + "' --script '" + (Dir() / "bad.txt").string() + "'");
  EXPECT_EQ(outcome.status, 1) << outcome.output;
  EXPECT_NE(outcome.output.find("bad.txt:2: unknown action 'jump'"), std::string::npos) << outcome.output;
  WriteFileAtomic(Dir() / "one.json", R"({"assets": {"oak": "capture/tree.vtree"}, "instances": []})");
  const test::Outcome scene =
      test::VoltreeCaptured("view '" + (Dir() / "one.json").string() + "' --unpruned '" + Asset().string() + "'");
  EXPECT_EQ(scene.status, 1) << scene.output;
  EXPECT_NE(scene.output.find("--unpruned applies to an asset (.vtree), not to the scene"), std::string::npos)
      << scene.output;
}

}  // namespace
}  // namespace voltree
