#include "render/instance_view.h"

namespace voltree {

// camera = R world + t, world = T + s Q p  =>  camera / s = (R Q) p + (R T + t) / s.
View ViewInAssetFrame(const View& view, const InstanceTransform& model) {
  model.Check();
  View out = view;
  out.pose.rotation = (view.pose.rotation * Eigen::Quaterniond(model.Rotation())).normalized();
  out.pose.translation = (view.pose.rotation * model.translation + view.pose.translation) / model.scale;
  return out;
}

}  // namespace voltree
