#include "mapmaker/point_geometry.hpp"

#include "core/image/image_pyramid.hpp"

namespace facadeslam {

PointGeometry source_geometry(const Camera& camera, const SE3d& T_src_w, const PatchSource& source,
                              const Eigen::Vector3d& p_w) {
  const Eigen::Vector2d at_level = ImagePyramid::level0_to_level(source.pixel_level0, source.level);
  const auto ray = [&](const Eigen::Vector2d& level_pixel) {
    return camera.unproject(ImagePyramid::level_to_level0(level_pixel, source.level));
  };
  const double depth = (T_src_w * p_w).z();
  const SE3d T_w_src = T_src_w.inverse();
  PointGeometry g =
      fronto_parallel_geometry(T_w_src.rotation_matrix(), T_w_src.translation(), ray(at_level),
                               ray(at_level + Eigen::Vector2d(1, 0)), ray(at_level + Eigen::Vector2d(0, 1)), depth);
  // Keep the position exactly as given (BA's result), not re-derived from the ray.
  g.p_w = p_w;
  g.normal_w = (T_w_src.translation() - p_w).normalized();
  return g;
}

}  // namespace facadeslam
