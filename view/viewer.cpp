#include "view/viewer.h"

#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <optional>

#include "core/colmap_model.h"
#include "core/error.h"
#include "core/files.h"
#include "core/fixed.h"
#include "core/image.h"
#include "core/vtree.h"
#include "render/gl.h"
#include "render/gl_context.h"
#include "render/scene.h"
#include "render/scene_renderer.h"
#include "render/tree_renderer.h"
#include "view/orbit_control.h"
#include "view/viewer_script.h"

namespace voltree {
namespace {

std::string g_glfw_error;  // GLFW reports errors through a callback, before the call returns

// What the window draws: one asset (TreeRenderer, as `render ASSET`) or a scene.
struct Drawing {
  std::optional<VtreeAsset> asset;
  std::unique_ptr<TreeRenderer> tree;
  std::optional<VtreeAsset> unpruned_asset;  // --unpruned: the same capture without pruning
  std::unique_ptr<TreeRenderer> unpruned_tree;
  std::optional<Scene> scene;
  std::unique_ptr<SceneRenderer> scene_renderer;

  // The asset drawn: the --unpruned one after U, when there is one.
  TreeRenderer& Tree(bool unpruned) const { return unpruned && unpruned_tree ? *unpruned_tree : *tree; }

  // The panel's pruning line: the share of billboards pruning took out of the asset drawn.
  std::string Pruning(bool unpruned) const {
    if (scene_renderer) return "pruning on (the scene's assets as built)";
    const bool off = unpruned && unpruned_asset;
    const VtreeAsset& shown = off ? *unpruned_asset : *asset;
    uint64_t before = 0;
    for (const VtreeLevel& level : shown.levels) before += level.billboards_before_pruning;
    const size_t kept = shown.BillboardCount();
    return Str(off              ? "pruning off (U)"
               : unpruned_asset ? "pruning on (U)"
                                : "pruning on (--unpruned to compare)",
               ": ", kept, " of ", before, " billboards in the asset (",
               FixedDecimals(before > 0 ? 100.0 * (1.0 - double(kept) / double(before)) : 0.0, 1), " % pruned)");
  }

  // Where `voltree render --orbit` starts.
  OrbitState Home() const {
    OrbitState home;
    if (scene_renderer) {  // SceneOrbitCameras
      const Sphere bounds = scene_renderer->Bounds(1.0);
      home.centre = bounds.centre;
      home.radius = std::max(bounds.radius, 1e-6);
      home.distance = 1.7 * home.radius;
      home.elevation_degrees = 25, home.azimuth_degrees = -60;
      return home;
    }
    // OrbitCameras: the input views' mean distance and elevation, the first view's azimuth.
    home.centre = 0.5 * (asset->bounds_min + asset->bounds_max);
    home.radius = std::max(0.5 * (asset->bounds_max - asset->bounds_min).norm(), 1e-6);
    double distance = 0, elevation = 0;
    for (const VtreeView& view : asset->views) {
      const Eigen::Vector3d d = view.position - home.centre;
      distance += d.norm();
      elevation += std::asin(std::clamp(d.z() / std::max(d.norm(), 1e-12), -1.0, 1.0));
    }
    const double n = double(std::max<size_t>(asset->views.size(), 1));
    home.distance = std::max(distance / n, home.radius * 1.1 * 1.01);
    home.elevation_degrees = elevation / n * 180 / M_PI;
    const Eigen::Vector3d first = asset->views.empty() ? Eigen::Vector3d(Eigen::Vector3d::UnitX())
                                                       : Eigen::Vector3d(asset->views[0].position - home.centre);
    home.azimuth_degrees = std::atan2(first.y(), first.x()) * 180 / M_PI;
    return home;
  }
};

struct PanelStats {
  double frame_ms = 0;
  size_t cells = 0, billboards = 0, instances_drawn = 1, instances_culled = 0;
  int min_level = -1, max_level = -1;
  ViewPair views;
  std::vector<size_t> cells_per_level;
};

// The window's state that callbacks and scripted events change.
struct Session {
  explicit Session(const OrbitState& home) : orbit(home) {}
  OrbitControl orbit;
  TreeRenderOptions render;
  bool dragging = false, panning = false;
  double last_x = 0, last_y = 0;
  bool screenshot_requested = false, quit = false;
  bool unpruned = false;  // U: draw the --unpruned asset
};

void PressKey(Session& session, const std::string& key) {
  if (key == "T") {
    session.render.tint_levels = !session.render.tint_levels;
  } else if (key == "L") {
    session.render.lod.rule = session.render.lod.rule == LodRule::kScreen ? LodRule::kPlanes : LodRule::kScreen;
  } else if (key == "V") {
    session.render.nearest_view_only = !session.render.nearest_view_only;
  } else if (key == "U") {
    session.unpruned = !session.unpruned;
  } else if (key == "R") {
    session.orbit.Reset();
  } else if (key == "W" || key == "S" || key == "A" || key == "D") {
    session.orbit.Fly(key == "W" ? 1 : key == "S" ? -1 : 0, key == "D" ? 1 : key == "A" ? -1 : 0);
  } else if (key == "P" || key == "F12") {
    session.screenshot_requested = true;
  } else if (key == "Escape") {
    session.quit = true;
  } else if (key.size() == 1 && key[0] >= '0' && key[0] <= '9') {
    const int level = key[0] - '0';
    session.render.lod.forced_level = session.render.lod.forced_level == level ? -1 : level;
  }
}

std::string KeyName(int key) {
  if (key >= GLFW_KEY_0 && key <= GLFW_KEY_9) return std::string(1, char('0' + key - GLFW_KEY_0));
  if (key >= GLFW_KEY_A && key <= GLFW_KEY_Z) return std::string(1, char('A' + key - GLFW_KEY_A));
  if (key == GLFW_KEY_F12) return "F12";
  if (key == GLFW_KEY_ESCAPE) return "Escape";
  return "";
}

Session& SessionOf(GLFWwindow* window) { return *static_cast<Session*>(glfwGetWindowUserPointer(window)); }

void OnKey(GLFWwindow* window, int key, int, int action, int) {
  if (action == GLFW_RELEASE || ImGui::GetIO().WantCaptureKeyboard) return;
  PressKey(SessionOf(window), KeyName(key));
}

void OnButton(GLFWwindow* window, int button, int action, int) {
  Session& session = SessionOf(window);
  const bool down = action == GLFW_PRESS && !ImGui::GetIO().WantCaptureMouse;
  if (button == GLFW_MOUSE_BUTTON_LEFT) session.dragging = down;
  if (button == GLFW_MOUSE_BUTTON_RIGHT) session.panning = down;
  glfwGetCursorPos(window, &session.last_x, &session.last_y);
}

void OnCursor(GLFWwindow* window, double x, double y) {
  Session& session = SessionOf(window);
  if (session.dragging) session.orbit.Turn(x - session.last_x, y - session.last_y);
  if (session.panning) session.orbit.Pan(x - session.last_x, y - session.last_y);
  session.last_x = x, session.last_y = y;
}

void OnScroll(GLFWwindow* window, double, double steps) {
  if (!ImGui::GetIO().WantCaptureMouse) SessionOf(window).orbit.Zoom(steps);
}

void Apply(Session& session, const ViewerEvent& event) {
  if (event.action == "drag") session.orbit.Turn(event.x, event.y);
  if (event.action == "pan") session.orbit.Pan(event.x, event.y);
  if (event.action == "scroll") session.orbit.Zoom(event.y);
  if (event.action == "key") PressKey(session, event.key);
  if (event.action == "screenshot") session.screenshot_requested = true;
  if (event.action == "quit") session.quit = true;
}

// The window's colour buffer as RGBA, top row first (opaque: the background is opaque).
Image8 ReadWindow(int width, int height) {
  Image8 image(width, height, 4);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadBuffer(GL_BACK);
  std::vector<uint8_t> rows(size_t(width) * height * 4);
  glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, rows.data());
  for (int y = 0; y < height; ++y)
    std::copy_n(rows.data() + size_t(height - 1 - y) * width * 4, size_t(width) * 4,
                image.pixels.data() + size_t(y) * width * 4);
  for (size_t i = 3; i < image.pixels.size(); i += 4) image.pixels[i] = 255;
  return image;
}

std::filesystem::path SaveScreenshot(const ViewerOptions& options, const View& camera, const Image8& image) {
  std::filesystem::create_directories(options.output);
  for (int i = 0;; ++i) {
    char stem[32];
    std::snprintf(stem, sizeof(stem), "view_%03d", i);
    const std::filesystem::path png = options.output / (std::string(stem) + ".png");
    if (std::filesystem::exists(png) || std::filesystem::exists(options.output / stem)) continue;
    ColmapModel model;
    model.cameras[1] = camera.camera;
    ColmapImage entry;
    entry.image_id = 1, entry.camera_id = 1, entry.name = png.filename().string(), entry.pose = camera.pose;
    model.images[1] = entry;
    WriteColmapText(options.output / stem, model);
    WriteImage(png, image);
    return png;
  }
}

void DrawPanel(const ViewerOptions& options, const Session& session, const PanelStats& stats, const GpuMemory& gpu,
               const std::string& renderer, const std::string& pruning) {
  ImGui::SetNextWindowPos(ImVec2(8, 8), ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowBgAlpha(0.7f);
  ImGui::Begin(options.input.filename().c_str(), nullptr, ImGuiWindowFlags_AlwaysAutoResize);
  ImGui::Text("%.1f ms per frame (%.0f fps)", stats.frame_ms, stats.frame_ms > 0 ? 1000 / stats.frame_ms : 0.0);
  ImGui::Text("cells %zu, billboards %zu", stats.cells, stats.billboards);
  ImGui::Text("levels %d..%d%s", stats.min_level, stats.max_level,
              session.render.lod.forced_level >= 0 ? " (forced)" : "");
  std::string per_level;
  for (size_t level = 0; level < stats.cells_per_level.size(); ++level)
    if (stats.cells_per_level[level] > 0)
      per_level += Str(per_level.empty() ? "" : ", ", "L", level, " ", stats.cells_per_level[level]);
  ImGui::Text("drawn per level: %s", per_level.c_str());
  const char* blend = session.render.nearest_view_only ? "nearest only" : "blended";
  if (stats.instances_drawn + stats.instances_culled > 1 || options.input.extension() == ".json")
    ImGui::Text("views: two per instance, %s", blend);
  else
    ImGui::Text("views %d + %d (%.2f / %.2f), %s", stats.views.first, stats.views.second, stats.views.first_weight,
                stats.views.second_weight, blend);
  ImGui::Text("instances %zu drawn, %zu culled", stats.instances_drawn, stats.instances_culled);
  ImGui::Text("GPU %.1f KiB (buffers %.1f, atlases %.1f)", gpu.Total() / 1024.0, gpu.buffers / 1024.0,
              gpu.atlas / 1024.0);
  ImGui::Text("LOD %s, tint %s", LodRuleName(session.render.lod.rule), session.render.tint_levels ? "on" : "off");
  ImGui::Text("%s", pruning.c_str());
  ImGui::TextDisabled("%s", renderer.c_str());
  ImGui::TextDisabled("drag turn, right drag pan, wheel zoom, WASD fly, R reset");
  ImGui::TextDisabled("T tint, L LOD rule, 0-9 level, V nearest view / blend, U pruning, P screenshot, Esc quit");
  ImGui::End();
}

// A window with an OpenGL 4.3 core context, current; after glfwInit.
GLFWwindow* OpenWindow(const ViewerOptions& options) {
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 4);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
  glfwWindowHint(GLFW_RESIZABLE, options.script.empty() ? GLFW_TRUE : GLFW_FALSE);
  GLFWwindow* window = glfwCreateWindow(
      options.width, options.height, ("voltree view: " + options.input.filename().string()).c_str(), nullptr, nullptr);
  if (!window)
    Fail("view: this display gives no OpenGL 4.3 core profile context (", g_glfw_error,
         "), which the renderer needs; 'voltree render' draws headless through EGL instead");
  glfwMakeContextCurrent(window);
  glfwSwapInterval(options.script.empty() ? 1 : 0);  // a script runs as fast as it can
  return window;
}

// The window's framebuffer cleared to the (straight) background, premultiplied as the renderer draws.
void ClearWindow(int width, int height, const std::array<float, 4>& background) {
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glViewport(0, 0, width, height);
  const auto& bg = background;
  glClearColor(bg[0] * bg[3], bg[1] * bg[3], bg[2] * bg[3], bg[3]);
  glClearDepth(1);
  glDepthMask(GL_TRUE);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
}

// One frame of the tree or the scene at `camera`, and what the panel shows of it.
PanelStats Draw(Drawing& drawing, const View& camera, const TreeRenderOptions& render, bool unpruned) {
  if (drawing.scene_renderer) {
    const SceneFrameStats frame = drawing.scene_renderer->Draw(camera, {render});
    return {frame.frame_ms,        frame.trees.cells,      frame.trees.billboards,
            frame.instances_drawn, frame.instances_culled, frame.trees.min_level,
            frame.trees.max_level, frame.trees.views,      frame.trees.cells_per_level};
  }
  const FrameStats frame = drawing.Tree(unpruned).Draw(camera, render);
  return {frame.frame_ms,  frame.cells, frame.billboards,     1, 0, frame.min_level,
          frame.max_level, frame.views, frame.cells_per_level};
}

// --unpruned: an asset of the same capture (the same input views), else U would compare two trees.
VtreeAsset ReadUnprunedAsset(const std::filesystem::path& file, const VtreeAsset& pruned) {
  VtreeAsset unpruned = ReadAsset(file);
  bool same = unpruned.views.size() == pruned.views.size();
  for (size_t i = 0; same && i < pruned.views.size(); ++i)
    same = (unpruned.views[i].position - pruned.views[i].position).norm() <= 1e-6 * pruned.size;
  if (!same)
    Fail("view: --unpruned ", file.string(), " has other input views (", unpruned.views.size(), ") than the asset (",
         pruned.views.size(), "); expected the same capture reconstructed with --prune 1");
  return unpruned;
}

// A screenshot waits until the LOD choice at its camera has settled (the cells drawn per level
// are those of the frame before: LOD hysteresis refines from the previous frame's choice), so
// that it shows what `render --cameras` draws from that camera however slowly frames come.
struct ScreenshotWait {
  static constexpr int kMaxFrames = 12;
  int frames = 0;  // drawn since the request
  std::vector<size_t> previous;
  // After each frame: whether the requested screenshot is taken of it.
  bool Ready(bool requested, const std::vector<size_t>& cells_per_level) {
    const bool ready = requested && frames > 0 && (cells_per_level == previous || frames >= kMaxFrames);
    frames = requested && !ready ? frames + 1 : 0;
    previous = cells_per_level;
    return ready;
  }
};

double Median(std::vector<double> values) {
  if (values.empty()) return 0;
  std::nth_element(values.begin(), values.begin() + values.size() / 2, values.end());
  return values[values.size() / 2];
}

}  // namespace

void ViewerOptions::Check() const {
  if (input.empty()) Fail("view: an asset (.vtree) or a scene (.json) is required");
  if (!std::filesystem::is_regular_file(input)) Fail(input.string(), ": file not found");
  if (width < 64 || height < 64 || width > 16384 || height > 16384)
    Fail("view: --size ", width, "x", height, " must be between 64 and 16384 on each side");
  if (!asset_folder.empty() && !IsSceneFile(input))
    Fail("view: --assets applies to a scene (.json), not to ", input.string());
  if (!unpruned.empty() && IsSceneFile(input))
    Fail("view: --unpruned applies to an asset (.vtree), not to the scene ", input.string());
  if (!unpruned.empty() && !std::filesystem::is_regular_file(unpruned)) Fail(unpruned.string(), ": file not found");
}

ViewerResult RunViewer(const ViewerOptions& options) {
  options.Check();
  const std::vector<ViewerEvent> script =
      options.script.empty() ? std::vector<ViewerEvent>{} : ReadViewerScript(options.script);
  Drawing drawing;
  std::vector<VtreeAsset> scene_assets;
  if (IsSceneFile(options.input)) {
    drawing.scene = LoadScene(options.input, {options.asset_folder});
    scene_assets = ReadSceneAssets(*drawing.scene);
  } else {
    drawing.asset = ReadAsset(options.input);
    if (!options.unpruned.empty()) drawing.unpruned_asset = ReadUnprunedAsset(options.unpruned, *drawing.asset);
  }

  glfwSetErrorCallback([](int, const char* message) { g_glfw_error = message; });
  if (!glfwInit())
    Fail("view: no display (", g_glfw_error,
         "); voltree view opens a window on a desktop session (DISPLAY or "
         "WAYLAND_DISPLAY); without one, 'voltree render' draws the same frames headless (--orbit N or --cameras "
         "MODEL)");
  struct Terminate {
    ~Terminate() { glfwTerminate(); }
  } terminate;
  GLFWwindow* window = OpenWindow(options);

  ViewerResult result;
  result.renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  if (drawing.scene) {
    drawing.scene_renderer = std::make_unique<SceneRenderer>(*drawing.scene, scene_assets);
  } else {
    drawing.tree = std::make_unique<TreeRenderer>(*drawing.asset);
    if (drawing.unpruned_asset) drawing.unpruned_tree = std::make_unique<TreeRenderer>(*drawing.unpruned_asset);
  }
  Session session(drawing.Home());
  glfwSetWindowUserPointer(window, &session);
  glfwSetKeyCallback(window, OnKey);
  glfwSetMouseButtonCallback(window, OnButton);
  glfwSetCursorPosCallback(window, OnCursor);
  glfwSetScrollCallback(window, OnScroll);
  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGui::GetIO().IniFilename = nullptr;                              // no imgui.ini beside the user's files
  ImGui_ImplGlfw_InitForOpenGL(window, /*install_callbacks=*/true);  // chains the callbacks above
  ImGui_ImplOpenGL3_Init("#version 430 core");

  size_t next_event = 0;
  const double start = glfwGetTime();
  PanelStats stats;
  ScreenshotWait screenshot_wait;
  std::vector<double> frame_ms;
  while (!glfwWindowShouldClose(window) && !session.quit) {
    glfwPollEvents();
    const double now = glfwGetTime() - start;
    // Scripted events run in order once their time has come, one batch per frame; a screenshot
    // holds the events after it until it is taken (slow frames must not merge them).
    while (!session.screenshot_requested && next_event < script.size() && script[next_event].seconds <= now)
      Apply(session, script[next_event++]);
    if (!script.empty() && next_event == script.size() && !session.screenshot_requested) session.quit = true;

    int width = 0, height = 0;
    glfwGetFramebufferSize(window, &width, &height);
    if (width < 1 || height < 1) continue;  // minimized
    const View camera = session.orbit.Camera(width, height);
    ClearWindow(width, height, options.background);
    stats = Draw(drawing, camera, session.render, session.unpruned);
    const GpuMemory gpu =
        drawing.scene_renderer ? drawing.scene_renderer->GpuBytes() : drawing.Tree(session.unpruned).GpuBytes();
    CheckGl("view: drawing");
    if (screenshot_wait.Ready(session.screenshot_requested, stats.cells_per_level)) {  // before the panel
      session.screenshot_requested = false;
      const std::filesystem::path png = SaveScreenshot(options, camera, ReadWindow(width, height));
      std::printf("%s (camera: %s; %zu billboards drawn; LOD %s; %s)\n", png.c_str(),
                  png.parent_path().append(png.stem().string()).c_str(), stats.billboards,
                  LodRuleName(session.render.lod.rule), drawing.Pruning(session.unpruned).c_str());
      result.screenshots.push_back(png);
    }
    if (options.panel) {
      ImGui_ImplOpenGL3_NewFrame();
      ImGui_ImplGlfw_NewFrame();
      ImGui::NewFrame();
      DrawPanel(options, session, stats, gpu, result.renderer, drawing.Pruning(session.unpruned));
      ImGui::Render();
      ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
    }
    glfwSwapBuffers(window);
    ++result.frames;
    frame_ms.push_back(stats.frame_ms);
  }
  ImGui_ImplOpenGL3_Shutdown();
  ImGui_ImplGlfw_Shutdown();
  ImGui::DestroyContext();
  drawing.tree.reset();
  drawing.unpruned_tree.reset();
  drawing.scene_renderer.reset();
  glfwDestroyWindow(window);
  result.median_ms = Median(std::move(frame_ms));
  return result;
}

}  // namespace voltree
