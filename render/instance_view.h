// A scene's view seen from an instance's own frame, for renderers that draw in the asset's
// coordinates without a model transform: the camera moved by the inverse of the instance's
// similarity, camera coordinates divided by its scale. Pixels are the same as drawing the
// instance in the world; depths shrink by the scale, so the frame's depth range [near, far] is
// [near, far] / scale in this view, and instances drawn so share one depth buffer.
#pragma once

#include "core/camera.h"
#include "render/instance_transform.h"

namespace voltree {

View ViewInAssetFrame(const View& view, const InstanceTransform& model);

}  // namespace voltree
