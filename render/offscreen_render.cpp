#include "render/offscreen_render.h"

#include <algorithm>

#include "core/error.h"

namespace voltree {

Image8 RenderOffscreen(std::unique_ptr<Framebuffer>& target, const Camera& camera,
                       const std::array<float, 4>& background, const std::function<void()>& draw) {
  camera.Check();
  if (!target || target->width() != camera.width || target->height() != camera.height)
    target = std::make_unique<Framebuffer>(camera.width, camera.height, ColorFormat::kRGBA8);
  target->Bind();
  const auto& bg = background;
  target->Clear(bg[0] * bg[3], bg[1] * bg[3], bg[2] * bg[3], bg[3]);  // premultiplied, like the blend
  draw();
  return Unpremultiply(target->ReadImage8());
}

Image8 Unpremultiply(const Image8& premultiplied) {
  if (premultiplied.channels != 4) Fail("unpremultiply: expected RGBA, got ", premultiplied.channels, " channels");
  Image8 out = premultiplied;
  for (size_t i = 0; i < out.pixels.size(); i += 4) {
    const int a = out.pixels[i + 3];
    for (int c = 0; c < 3; ++c)
      out.pixels[i + c] = a == 0 ? 0 : uint8_t(std::min(255, (int(out.pixels[i + c]) * 255 + a / 2) / a));
  }
  return out;
}

}  // namespace voltree
