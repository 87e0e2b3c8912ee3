#include "web/page_camera.h"

#include <sstream>

namespace voltree {

std::optional<std::string> PageCameraParameter(const View& view) {
  const Camera& camera = view.camera;
  if (camera.model != CameraModel::kPinhole && camera.model != CameraModel::kSimplePinhole) return std::nullopt;
  const Eigen::Quaterniond& q = view.pose.rotation;
  const Eigen::Vector3d& t = view.pose.translation;
  std::ostringstream out;
  out.precision(17);
  out << "camera=" << camera.width << ',' << camera.height << ',' << camera.FocalX() << ',' << camera.FocalY() << ','
      << camera.PrincipalPoint().x() << ',' << camera.PrincipalPoint().y() << ',' << q.w() << ',' << q.x() << ','
      << q.y() << ',' << q.z() << ',' << t.x() << ',' << t.y() << ',' << t.z();
  return out.str();
}

}  // namespace voltree
