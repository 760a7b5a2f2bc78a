#include "render/ar/follow_camera.hpp"

#include <cmath>
#include <numbers>

namespace facadeslam::render::ar {

MapViewCamera follow_camera(const Eigen::Isometry3d& T_w_c, const ViewAxes& axes, double scene_depth, int width,
                            int height, const FollowCameraOptions& options) {
  const Eigen::Vector3d up = axes.up_w.normalized();
  // The camera's heading made horizontal; looking straight up or down, the
  // map's own forward.
  Eigen::Vector3d heading = T_w_c.linear().col(2);
  heading -= heading.dot(up) * up;
  heading = heading.norm() > 1e-6 ? heading.normalized() : axes.forward_w.normalized();
  const Eigen::Vector3d centre = T_w_c.translation();
  const double depth = scene_depth > 0.0 ? scene_depth : 1.0;
  const Eigen::Vector3d eye = centre - options.behind * depth * heading + options.above * depth * up;
  const Eigen::Vector3d target = centre + options.look_ahead * depth * heading;

  // Camera axes: z towards the target, x right (z x up), y down.
  const Eigen::Vector3d z = (target - eye).normalized();
  const Eigen::Vector3d x = z.cross(up).normalized();
  const Eigen::Vector3d y = z.cross(x);
  MapViewCamera camera;
  camera.T_w_c.linear().col(0) = x;
  camera.T_w_c.linear().col(1) = y;
  camera.T_w_c.linear().col(2) = z;
  camera.T_w_c.translation() = eye;
  const double f = 0.5 * width / std::tan(0.5 * options.horizontal_fov_deg * std::numbers::pi / 180.0);
  camera.intrinsics = {width, height, f, f, 0.5 * (width - 1), 0.5 * (height - 1)};
  camera.near = 0.01 * depth;
  return camera;
}

}  // namespace facadeslam::render::ar
