// The studio's cameras in GLSL: the exact COLMAP projection (distortion included) from world
// points to pixel coordinates, and its inverse for per-pixel rays. Shared by the tree and the
// backdrop so both agree with View::WorldToPixel.
#pragma once

#include <string>

#include "core/camera.h"
#include "render/shader.h"

namespace voltree {

// GLSL (no #version line) declaring the camera uniforms and
//   vec4 ProjectToClip(vec3 world)  -- clip position whose window coordinates are the pixel
//                                      coordinates (times the supersampling of the viewport)
//   vec3 PixelRay(vec2 pixel)       -- unit world direction through a pixel position
//   vec3 CameraCenter()
extern const std::string kStudioProjectionGlsl;

// Sets the uniforms of kStudioProjectionGlsl for `view`; depth maps [near, far] to [-1, 1].
void SetStudioCamera(const ShaderProgram& program, const View& view, double near, double far);

}  // namespace voltree
