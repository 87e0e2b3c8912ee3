// The off-screen frame behind TreeRenderer::Render and SceneRenderer::Render: a framebuffer of
// the camera's size, cleared to the background, drawn into, read back with straight alpha.
#pragma once

#include <array>
#include <functional>
#include <memory>

#include "core/camera.h"
#include "core/image.h"
#include "render/framebuffer.h"

namespace voltree {

// Binds `target` (made, or remade when the camera's size changed), clears it to `background`
// (straight RGBA in [0, 1], premultiplied like the blend), runs `draw` and reads the frame back.
Image8 RenderOffscreen(std::unique_ptr<Framebuffer>& target, const Camera& camera,
                       const std::array<float, 4>& background, const std::function<void()>& draw);

// Straight alpha from premultiplied RGBA8 (rounded; colour 0 where alpha is 0).
Image8 Unpremultiply(const Image8& premultiplied);

}  // namespace voltree
