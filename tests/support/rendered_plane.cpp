#include "tests/support/rendered_plane.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/Geometry>
#include <opencv2/imgproc.hpp>

namespace facadeslam::test {

RenderedPlane make_plane(int seed) {
  RenderedPlane plane;
  cv::Mat texture(1200, 1600, CV_8UC1, cv::Scalar(128));
  cv::RNG rng(static_cast<std::uint64_t>(seed));
  for (int i = 0; i < 2500; ++i) {
    // Log-uniform sizes so that every pyramid level of every view has corners.
    const int w = static_cast<int>(std::exp(rng.uniform(std::log(3.0), std::log(80.0))));
    const int h = static_cast<int>(std::exp(rng.uniform(std::log(3.0), std::log(80.0))));
    // y before x: the order GCC evaluated the two arguments in when the tests'
    // thresholds were set (the order of a call's arguments is unspecified,
    // and clang's gave another texture).
    const int y = rng.uniform(-h, texture.rows);
    const cv::Point p(rng.uniform(-w, texture.cols), y);
    cv::rectangle(texture, cv::Rect(p, cv::Size(w, h)), cv::Scalar(rng.uniform(20, 236)), cv::FILLED);
  }
  cv::GaussianBlur(texture, plane.texture, cv::Size(0, 0), 1.0);
  return plane;
}

Camera test_camera() { return Camera(640, 480, PinholeRadTan{500.0, 500.0, 319.5, 239.5}); }

cv::Mat render(const RenderedPlane& plane, const Camera& camera, const SE3d& T_c_w) {
  constexpr int k = 4;  // supersampling factor
  Eigen::Matrix3d K_k;
  K_k << k * camera.fx(), 0, (camera.cx() + 0.5) * k - 0.5, 0, k * camera.fy(), (camera.cy() + 0.5) * k - 0.5, 0, 0, 1;
  const Eigen::Matrix3d R = T_c_w.rotation_matrix();
  Eigen::Matrix3d P;  // plane (X, Y, 1) -> camera, for points (X, Y, plane_depth)
  P.col(0) = R.col(0);
  P.col(1) = R.col(1);
  P.col(2) = plane.plane_depth * R.col(2) + T_c_w.translation();
  Eigen::Matrix3d S;  // texture pixel -> plane (X, Y, 1)
  S << plane.texel, 0, -plane.texel * (plane.texture.cols - 1) / 2.0, 0, plane.texel,
      -plane.texel * (plane.texture.rows - 1) / 2.0, 0, 0, 1;
  const Eigen::Matrix3d H = K_k * P * S;
  cv::Mat Hcv(3, 3, CV_64F);
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) Hcv.at<double>(r, c) = H(r, c);
  cv::Mat big, image;
  cv::warpPerspective(plane.texture, big, Hcv, cv::Size(camera.width() * k, camera.height() * k), cv::INTER_LINEAR,
                      cv::BORDER_CONSTANT, cv::Scalar(128));
  cv::resize(big, image, cv::Size(camera.width(), camera.height()), 0, 0, cv::INTER_AREA);
  return image;
}

SE3d view_pose(const RenderedPlane& plane, double distance, double roll, double tilt, double dx, double dy) {
  const Eigen::Matrix3d R_w_c =
      (Eigen::AngleAxisd(tilt, Eigen::Vector3d::UnitX()) * Eigen::AngleAxisd(roll, Eigen::Vector3d::UnitZ()))
          .toRotationMatrix();
  const Eigen::Vector3d target(dx, dy, plane.plane_depth);
  const Eigen::Vector3d centre = target - distance * R_w_c.col(2);
  const Eigen::Matrix3d R_c_w = R_w_c.transpose();
  return SE3d(R_c_w, Eigen::Vector3d(-R_c_w * centre));
}

std::vector<PlanePoint> points_from_source(const RenderedPlane& plane, const Camera& camera,
                                           const std::shared_ptr<const ImagePyramid>& source, int level,
                                           int max_points) {
  std::vector<Corner> corners = source->level(level).corners;
  std::sort(corners.begin(), corners.end(), [](const Corner& a, const Corner& b) { return a.score > b.score; });
  const cv::Mat& image = source->level(level).image;
  const int border = 12;
  std::vector<PlanePoint> points;
  std::vector<Eigen::Vector2d> taken;
  for (const Corner& c : corners) {
    if (static_cast<int>(points.size()) >= max_points) break;
    if (c.x < border || c.y < border || c.x >= image.cols - border || c.y >= image.rows - border) continue;
    const Eigen::Vector2d xl(c.x, c.y);
    if (std::any_of(taken.begin(), taken.end(), [&](const Eigen::Vector2d& t) { return (t - xl).norm() < 12.0; }))
      continue;
    taken.push_back(xl);
    PlanePoint p;
    p.source.keyframe_id = 0;
    p.source.pyramid = source;
    p.source.level = level;
    p.source.pixel_level0 = ImagePyramid::level_to_level0(xl, level);
    const Eigen::Vector3d ray = camera.unproject(p.source.pixel_level0);
    const Eigen::Vector3d right = camera.unproject(ImagePyramid::level_to_level0(xl + Eigen::Vector2d(1, 0), level));
    const Eigen::Vector3d down = camera.unproject(ImagePyramid::level_to_level0(xl + Eigen::Vector2d(0, 1), level));
    p.geometry = fronto_parallel_geometry(Eigen::Matrix3d::Identity(), Eigen::Vector3d::Zero(), ray, right, down,
                                          plane.plane_depth);
    points.push_back(p);
  }
  return points;
}

}  // namespace facadeslam::test
