#include "tests/render/render_test_scenes.hpp"

#include <cmath>

namespace facadeslam::test {

cv::Mat checkerboard(int columns, int rows, int square) {
  cv::Mat board(rows * square, columns * square, CV_8UC1);
  for (int y = 0; y < board.rows; ++y)
    for (int x = 0; x < board.cols; ++x) board.at<std::uint8_t>(y, x) = ((x / square + y / square) % 2) ? 230 : 25;
  return board;
}

Eigen::Isometry3d look_at(const Eigen::Vector3d& eye, const Eigen::Vector3d& target, const Eigen::Vector3d& up,
                          double roll) {
  const Eigen::Vector3d z = (target - eye).normalized();
  const Eigen::Vector3d x = z.cross(up).normalized();  // image right
  const Eigen::Vector3d y = z.cross(x);                // image down
  Eigen::Matrix3d R;
  R << x, y, z;
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = R * Eigen::AngleAxisd(roll, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  T.translation() = eye;
  return T;
}

ReferenceHit cast_ray(const std::vector<ReferenceQuad>& quads, const Camera& camera, const Eigen::Isometry3d& T_w_c,
                      double x, double y) {
  return cast_ray(quads, T_w_c, camera.unproject(Eigen::Vector2d(x, y)));
}

ReferenceHit cast_ray(const std::vector<ReferenceQuad>& quads, const Eigen::Isometry3d& T_w_c,
                      const Eigen::Vector3d& ray_c) {
  const Eigen::Vector3d origin = T_w_c.translation();
  const Eigen::Vector3d direction = T_w_c.linear() * ray_c;
  ReferenceHit best;
  for (std::size_t i = 0; i < quads.size(); ++i) {
    const ReferenceQuad& q = quads[i];
    const Eigen::Vector3d normal = q.right.cross(q.down);
    const double denominator = normal.dot(direction);
    if (std::abs(denominator) < 1e-12) continue;
    const double t = normal.dot(q.top_left - origin) / denominator;  // = z, since ray_c.z = 1
    if (t <= 0.05) continue;
    const Eigen::Vector3d offset = origin + t * direction - q.top_left;
    const double a = offset.dot(q.right) / q.right.squaredNorm();
    const double b = offset.dot(q.down) / q.down.squaredNorm();
    if (a < 0.0 || a >= 1.0 || b < 0.0 || b >= 1.0) continue;
    if (best.quad >= 0 && t >= best.z) continue;
    const std::uint8_t label = q.labels.empty()
                                   ? q.label
                                   : q.labels.at<std::uint8_t>(static_cast<int>(std::floor(b * q.labels.rows)),
                                                               static_cast<int>(std::floor(a * q.labels.cols)));
    if (label == render::kTransparentLabel) continue;  // a hole in the surface
    best.quad = static_cast<int>(i);
    best.z = t;
    best.a = a;
    best.b = b;
    best.label = label;
  }
  return best;
}

}  // namespace facadeslam::test
