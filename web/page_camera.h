// A camera as the web page's URL takes it (docs/web.md): camera=W,H,FX,FY,CX,CY,QW,QX,QY,QZ,TX,TY,TZ,
// cameras.txt's PINHOLE parameters then images.txt's pose, so a page opens where a render was taken.
#pragma once

#include <optional>
#include <string>

#include "core/camera.h"

namespace voltree {

// "camera=..." with full precision; nullopt for a camera with lens distortion (the page draws
// pinholes only).
std::optional<std::string> PageCameraParameter(const View& view);

}  // namespace voltree
