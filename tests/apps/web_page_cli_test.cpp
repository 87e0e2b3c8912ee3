// `voltree web` in a real browser: a tiny captured oak (8 views at 96x96, 4 levels, about 3 s)
// is written as a page, opened from disk by headless Chromium (WebGL2 on SwiftShader) with a
// COLMAP camera in the URL, and its screenshot compared with `voltree render` from the same
// camera over the same grey: RGB PSNR >= 35 dB. Two cameras, the page's DXT5 decoder, a scene of
// three instances on a ground, the frame `voltree eval` embeds in its report, and the page's
// errors (corrupt asset, unknown format version).
// Each check has a control that must fail it (the other camera's render, a blank grey image).
// About 40 s, most of it Chromium starting.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <sstream>
#include <string>

#include "core/camera.h"
#include "core/colmap_model.h"
#include "core/files.h"
#include "core/image.h"
#include "core/image_metrics.h"
#include "pipeline/voltree_binary.h"
#include "tiny_asset_suite.h"

namespace voltree {
namespace {

namespace fs = std::filesystem;

constexpr int kWidth = 256, kHeight = 256;
constexpr double kMinPsnr = 35;

// The flags that give headless Chromium WebGL2 without a GPU: ANGLE on SwiftShader (software
// Vulkan), which the browser only enables for WebGL when told that software is acceptable.
// (Headless Chromium makes a temporary profile of its own for each run.)
std::string Chromium(const std::string& action, const std::string& url, int width = kWidth, int height = kHeight) {
  return "timeout 120 chromium --headless=new --no-sandbox --disable-gpu --use-angle=swiftshader "
         "--enable-unsafe-swiftshader --force-device-scale-factor=1 --hide-scrollbars --window-size=" +
         std::to_string(width) + "," + std::to_string(height) + " --virtual-time-budget=10000 " + action + " '" + url +
         "' 2>/dev/null";
}

// The URL form of a camera: cameras.txt's PINHOLE parameters, then images.txt's pose.
std::string CameraParameter(const View& view) {
  const Eigen::Quaterniond& q = view.pose.rotation;
  const Eigen::Vector3d& t = view.pose.translation;
  std::ostringstream out;
  out.precision(17);
  out << view.camera.width << ',' << view.camera.height << ',' << view.camera.FocalX() << ',' << view.camera.FocalY()
      << ',' << view.camera.PrincipalPoint().x() << ',' << view.camera.PrincipalPoint().y() << ',' << q.w() << ','
      << q.x() << ',' << q.y() << ',' << q.z() << ',' << t.x() << ',' << t.y() << ',' << t.z();
  return out.str();
}

View LookingAt(const std::string& name, const Eigen::Vector3d& eye, const Eigen::Vector3d& target, double focal) {
  View view;
  view.name = name;
  view.camera = Camera::Pinhole(kWidth, kHeight, focal, focal, 0.5 * kWidth, 0.5 * kHeight);
  view.pose = Pose::LookAt(eye, target, Eigen::Vector3d::UnitZ());
  return view;
}

class WebPage : public test::TinyAssetSuite {
 protected:
  static void SetUpTestSuite() { BuildTinyAsset("voltree_web_"); }
  void SetUp() override { RequireToolAndAsset("chromium", "chromium"); }

  // `voltree render` of one camera over grey (a fresh renderer: no LOD history, like a page load).
  static Image8 Render(const std::string& input, const View& view, const std::string& name) {
    ColmapModel model;
    model.cameras[1] = view.camera;
    ColmapImage image;
    image.image_id = 1, image.camera_id = 1, image.name = name + ".png", image.pose = view.pose;
    model.images[1] = image;
    const fs::path cameras = Dir() / ("cameras_" + name), frames = Dir() / ("render_" + name);
    WriteColmapText(cameras, model);
    const test::Outcome outcome =
        test::VoltreeCaptured("render '" + input + "' --cameras '" + cameras.string() +
                              "' --background 128,128,128 --quiet -o '" + frames.string() + "'");
    EXPECT_EQ(outcome.status, 0) << outcome.output;
    return ReadImage8(frames / (name + ".png"), 4);
  }

  static fs::path WritePage(const std::string& input, const std::string& name) {
    const fs::path page = Dir() / ("page_" + name);
    const test::Outcome outcome = test::VoltreeCaptured("web '" + input + "' -o '" + page.string() + "'");
    EXPECT_EQ(outcome.status, 0) << outcome.output;
    return page;
  }

  static std::string Url(const fs::path& page, const std::string& query) {
    return "file://" + (page / "index.html").string() + "?" + query;
  }

  static Image8 Screenshot(const fs::path& page, const std::string& query, const std::string& name) {
    const fs::path png = Dir() / ("shot_" + name + ".png");
    std::system(Chromium("--screenshot='" + png.string() + "'", Url(page, query)).c_str());
    if (!fs::exists(png)) {
      ADD_FAILURE() << "chromium wrote no screenshot of " << Url(page, query);
      return Image8(kWidth, kHeight, 4, 0);
    }
    return ReadImage8(png, 4);
  }

  static std::string Dom(const fs::path& page, const std::string& query) {
    return test::Shell(Chromium("--dump-dom", Url(page, query))).output;
  }

  static double Psnr(const Image8& a, const Image8& b) {
    EXPECT_EQ(a.width, b.width);
    EXPECT_EQ(a.height, b.height);
    if (a.width != b.width || a.height != b.height) return 0;
    return CompareViews(a, b).rgb_psnr;
  }
};

TEST_F(WebPage, MatchesRenderFromTwoCameras) {
  const fs::path page = WritePage(Asset().string(), "asset");
  // A held-out camera of the studio (at 256x256), and a closer one that draws finer levels.
  View held_out = ReadColmapText(Dir() / "capture" / "truth" / "sparse").Views().at(0);
  held_out.camera =
      Camera::Pinhole(kWidth, kHeight, held_out.camera.FocalX() * kWidth / held_out.camera.width,
                      held_out.camera.FocalY() * kHeight / held_out.camera.height, 0.5 * kWidth, 0.5 * kHeight);
  const View close = LookingAt("close", Eigen::Vector3d(9, -11, 5), Eigen::Vector3d(0, 0, 4), 300);
  const Image8 render_a = Render(Asset().string(), held_out, "held_out");
  const Image8 render_b = Render(Asset().string(), close, "close");
  const Image8 page_a = Screenshot(page, "ui=0&background=128,128,128&camera=" + CameraParameter(held_out), "held_out");
  const Image8 page_b = Screenshot(page, "ui=0&background=128,128,128&camera=" + CameraParameter(close), "close");
  const Image8 grey(kWidth, kHeight, 4, 128);
  const double a = Psnr(page_a, render_a), b = Psnr(page_b, render_b);
  std::printf("page vs render: held-out camera %.2f dB, close camera %.2f dB\n", a, b);
  EXPECT_GE(a, kMinPsnr);
  EXPECT_GE(b, kMinPsnr);
  // Controls: the other camera's render, and the bare background, are far below.
  EXPECT_LT(Psnr(page_a, render_b), kMinPsnr - 10);
  EXPECT_LT(Psnr(page_b, Image8(kWidth, kHeight, 4, 255)), kMinPsnr - 10);
  EXPECT_LT(Psnr(page_a, grey), kMinPsnr - 10);
  EXPECT_LT(Psnr(page_b, grey), kMinPsnr - 10);
}

TEST_F(WebPage, DecodesDxt5WithoutTheS3tcExtension) {
  const fs::path page = WritePage(Asset().string(), "decoded");
  const View view = LookingAt("decoded", Eigen::Vector3d(-12, -6, 6), Eigen::Vector3d(0, 0, 4), 200);
  const Image8 render = Render(Asset().string(), view, "decoded");
  const Image8 shot = Screenshot(page, "ui=0&background=128,128,128&s3tc=0&camera=" + CameraParameter(view), "decoded");
  const double psnr = Psnr(shot, render);
  std::printf("page (DXT5 decoded in JavaScript) vs render: %.2f dB\n", psnr);
  EXPECT_GE(psnr, kMinPsnr);
  EXPECT_LT(Psnr(shot, Image8(kWidth, kHeight, 4, 128)), kMinPsnr - 10);
}

TEST_F(WebPage, SceneOfThreeInstancesMatchesRender) {
  const fs::path scene = Dir() / "capture" / "three.json";
  WriteFileAtomic(scene, R"({
  "assets": {"oak": "tree.vtree"},
  "ground": {"size": 60, "colour": [96, 110, 70]},
  "instances": [
    {"asset": "oak", "position": [-9, 0, 0], "rotation": 0},
    {"asset": "oak", "position": [6, 7, 0], "rotation": 120, "scale": 0.8},
    {"asset": "oak", "position": [4, -8, 0], "rotation": 250, "scale": 1.2}
  ]
})");
  const fs::path page = WritePage(scene.string(), "scene");
  const View view = LookingAt("scene", Eigen::Vector3d(30, -24, 14), Eigen::Vector3d(0, 0, 3), 180);
  const Image8 render = Render(scene.string(), view, "scene");
  const Image8 shot = Screenshot(page, "ui=0&background=128,128,128&camera=" + CameraParameter(view), "scene");
  const double psnr = Psnr(shot, render);
  std::printf("scene page vs render: %.2f dB\n", psnr);
  EXPECT_GE(psnr, kMinPsnr);
  EXPECT_LT(Psnr(shot, Image8(kWidth, kHeight, 4, 128)), kMinPsnr - 10);
  const std::string dom = Dom(page, "camera=" + CameraParameter(view));
  EXPECT_NE(dom.find("instances 3 drawn, 0 culled"), std::string::npos) << "the stats line: " << dom.substr(0, 2000);
}

// `voltree eval` embeds the page beside each held-out truth; the frame, opened at the camera's
// size, shows what eval measured (its voltree image over the same grey, no LOD history).
TEST_F(WebPage, ReportFrameMatchesEvalsImage) {
  const fs::path report = Dir() / "report";
  const test::Outcome outcome =
      test::VoltreeCaptured("eval '" + (Dir() / "capture").string() +
                            "' --eval-levels auto --no-input --no-plots --quiet --report '" + report.string() + "'");
  ASSERT_EQ(outcome.status, 0) << outcome.output;
  const std::string html = ReadFile(report / "index.html");
  const size_t frame = html.find("<iframe src=\"");
  ASSERT_NE(frame, std::string::npos) << "no interactive frame in the report";
  const size_t start = frame + 13, end = html.find('"', start);
  std::string src;  // the attribute, HTML-unescaped (only &amp; occurs in it)
  for (size_t i = start; i < end; ++i) {
    src += html[i];
    if (html.compare(i, 5, "&amp;") == 0) i += 4;
  }
  ASSERT_EQ(src.rfind("eval/web/index.html?", 0), 0u) << src;
  const size_t query = src.find('?') + 1;
  const View held_out = ReadColmapText(Dir() / "capture" / "truth" / "sparse").Views().at(0);
  const fs::path png = Dir() / "shot_report.png";
  const std::string command =
      Chromium("--screenshot='" + png.string() + "'",
               "file://" + (report / "eval" / "web" / "index.html").string() + "?" + src.substr(query),
               held_out.camera.width, held_out.camera.height);
  std::system(command.c_str());
  ASSERT_TRUE(fs::exists(png)) << command;
  const Image8 shot = ReadImage8(png, 4);
  const Image8 measured =
      ReadImage8(report / "eval" / "held_out" / (fs::path(held_out.name).stem().string() + "_voltree.png"), 4);
  const double psnr = Psnr(shot, measured);
  std::printf("report frame vs eval's image: %.2f dB\n", psnr);
  EXPECT_GE(psnr, kMinPsnr);
}

// data.js with the asset's bytes changed by `edit` (on the base64 text).
void EditData(const fs::path& page, const std::function<void(std::string&)>& edit) {
  std::string data = ReadFile(page / "data.js");
  edit(data);
  WriteFileAtomic(page / "data.js", data);
}

std::string ErrorBox(const std::string& dom) {
  const size_t start = dom.find("<pre id=\"error\""), end = dom.find("</pre>", start);
  return start == std::string::npos ? "" : dom.substr(start, end - start);
}

TEST_F(WebPage, CorruptAssetShowsAReadableError) {
  const fs::path page = WritePage(Asset().string(), "corrupt");
  EXPECT_EQ(ErrorBox(Dom(page, "")), "<pre id=\"error\" hidden=\"\">") << "a good asset shows no error";
  EditData(page, [](std::string& data) {
    const size_t middle = data.find("\"base64\":\"") + 10 + 20000;  // inside the BBRD / ATLS payloads
    data[middle] = data[middle] == 'A' ? 'B' : 'A';
  });
  const std::string box = ErrorBox(Dom(page, ""));
  EXPECT_EQ(box.find("hidden"), std::string::npos) << box;
  EXPECT_NE(box.find("tree.vtree: chunk"), std::string::npos) << box;
  EXPECT_NE(box.find("checksum mismatch"), std::string::npos) << box;
  // And it is on screen: the error box is drawn, not a blank canvas.
  const Image8 shot = Screenshot(page, "", "corrupt");
  EXPECT_LT(Psnr(shot, Image8(kWidth, kHeight, 4, 128)), kMinPsnr - 10);
}

TEST_F(WebPage, UnknownFormatVersionNamesTheExpectedOne) {
  const fs::path page = WritePage(Asset().string(), "version");
  EditData(page, [](std::string& data) {
    // "VTREE\0\0\0" + u32 version 2 in base64 is "VlRSRUUAAAACAAAA"; version 1 (the 10-byte records) is
    // "...ABAAAA".
    const size_t at = data.find("VlRSRUUAAAACAAAA");
    ASSERT_NE(at, std::string::npos);
    data.replace(at, 16, "VlRSRUUAAAABAAAA");
  });
  const std::string box = ErrorBox(Dom(page, ""));
  EXPECT_NE(box.find("format version 1 is not supported (this page reads version 2; rebuild the asset"),
            std::string::npos)
      << box;
}

TEST_F(WebPage, RefusesAnExistingFolderAndMissingSceneAssets) {
  const fs::path page = Dir() / "page_existing";
  fs::create_directories(page);
  WriteFileAtomic(page / "mine.txt", "keep");
  test::Outcome outcome = test::VoltreeCaptured("web '" + Asset().string() + "' -o '" + page.string() + "'");
  EXPECT_EQ(outcome.status, 1);
  EXPECT_NE(outcome.output.find("--force"), std::string::npos) << outcome.output;
  EXPECT_EQ(ReadFile(page / "mine.txt"), "keep");
  outcome = test::VoltreeCaptured("web '" + Asset().string() + "' -o '" + page.string() + "' --force");
  EXPECT_EQ(outcome.status, 0) << outcome.output;
  EXPECT_TRUE(fs::exists(page / "index.html"));

  const fs::path scene = Dir() / "missing.json";
  WriteFileAtomic(scene, R"({"assets": {"elm": "elm.vtree"}, "instances": [{"asset": "elm", "position": [0, 0, 0]}]})");
  outcome = test::VoltreeCaptured("web '" + scene.string() + "' -o '" + (Dir() / "page_missing").string() + "'");
  EXPECT_EQ(outcome.status, 1);
  EXPECT_NE(outcome.output.find("elm.vtree"), std::string::npos) << outcome.output;
  EXPECT_NE(outcome.output.find("not found"), std::string::npos) << outcome.output;
  EXPECT_FALSE(fs::exists(Dir() / "page_missing"));
}

}  // namespace
}  // namespace voltree
