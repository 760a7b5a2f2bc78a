#include "render/projection.hpp"

namespace facadeslam::render {

Eigen::Matrix4d clip_from_camera(const PinholeIntrinsics& k, double near) {
  const double w = k.width, h = k.height;
  Eigen::Matrix4d m = Eigen::Matrix4d::Zero();
  m(0, 0) = 2.0 * k.fx / w;
  m(0, 2) = 2.0 * (k.cx + 0.5) / w - 1.0;
  m(1, 1) = 2.0 * k.fy / h;
  m(1, 2) = 2.0 * (k.cy + 0.5) / h - 1.0;
  m(2, 3) = near;  // clip_z = near (times the homogeneous 1)
  m(3, 2) = 1.0;   // clip_w = z
  return m;
}

Eigen::Vector2d pixel_from_clip(const PinholeIntrinsics& k, const Eigen::Vector4d& clip) {
  const double x_ndc = clip.x() / clip.w(), y_ndc = clip.y() / clip.w();
  const double x_window = 0.5 * (x_ndc + 1.0) * k.width;
  const double y_window = 0.5 * (y_ndc + 1.0) * k.height;
  return {x_window - 0.5, y_window - 0.5};
}

}  // namespace facadeslam::render
