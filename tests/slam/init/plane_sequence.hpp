#pragma once
// Image sequences of a textured facade plane for the KLT and initialiser
// tests: each frame is the texture warped (cv::warpPerspective) by the
// homography that a known camera pose induces, so the true motion of every
// pixel is known exactly.
#include <filesystem>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <opencv2/core.hpp>
#include <opencv2/core/eigen.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "core/camera/camera.hpp"
#include "core/lie/se3.hpp"
#include "tests/slam/init/synthetic_two_view.hpp"

namespace facadeslam::test {

// A corner-rich grey texture that needs no data files: blurred noise at
// three scales plus a grid of "windows" (rectangles) of random brightness.
inline cv::Mat synthetic_facade_texture(int width, int height, unsigned seed) {
  cv::RNG rng(seed);
  cv::Mat texture(height, width, CV_32F, cv::Scalar(0.0f));
  for (const int cell : {4, 16, 64}) {
    cv::Mat small(height / cell + 2, width / cell + 2, CV_32F);
    rng.fill(small, cv::RNG::UNIFORM, 0.0, 1.0);
    cv::Mat large;
    cv::resize(small, large, cv::Size(width, height), 0, 0, cv::INTER_CUBIC);
    texture += large * (cell == 4 ? 40.0 : 50.0);
  }
  cv::Mat image;
  texture.convertTo(image, CV_8U, 1.0, 20.0);
  for (int y = 20; y + 50 < height; y += 90)
    for (int x = 20 + rng.uniform(0, 20); x + 40 < width; x += 70 + rng.uniform(0, 20)) {
      // One draw a statement: a call's arguments are evaluated in the compiler's order.
      const int window_width = 36 + rng.uniform(0, 10);
      const int window_height = 46 + rng.uniform(0, 10);
      const int brightness = rng.uniform(0, 255);
      cv::rectangle(image, cv::Rect(x, y, window_width, window_height), cv::Scalar(brightness), cv::FILLED);
    }
  cv::GaussianBlur(image, image, cv::Size(3, 3), 0.8);
  return image;
}

// The facade photo of the shared data (grey), or an empty image.
inline cv::Mat building_texture(const std::filesystem::path& shared_data) {
  return cv::imread((shared_data / "opencv-samples" / "building.jpg").string(), cv::IMREAD_GRAYSCALE);
}

// A plane in the first camera's frame carrying the texture: its centre pixel
// sits at `centre_c0`, texture x and y run along the plane's axes, one
// texture pixel is `metres_per_pixel` wide.
struct TexturedPlane {
  cv::Mat texture;
  Eigen::Vector3d centre_c0{0.0, 0.0, 2.0};
  Eigen::Matrix3d axes = Eigen::Matrix3d::Identity();  // columns: texture x, texture y, normal
  double metres_per_pixel = 0.004;

  // Texture pixel (u, v, 1) -> point in camera 0's frame.
  Eigen::Matrix3d texture_to_c0() const {
    const double cu = (texture.cols - 1) / 2.0, cv_ = (texture.rows - 1) / 2.0;
    Eigen::Matrix3d A;
    A.col(0) = axes.col(0) * metres_per_pixel;
    A.col(1) = axes.col(1) * metres_per_pixel;
    A.col(2) = centre_c0 - metres_per_pixel * (cu * axes.col(0) + cv_ * axes.col(1));
    return A;
  }
  Eigen::Vector3d normal_c0() const { return axes.col(2); }
  double distance_c0() const { return normal_c0().dot(centre_c0); }
};

// The plane turned by `yaw_deg` about the vertical axis, 2 m ahead.
inline TexturedPlane facade_plane(cv::Mat texture, double yaw_deg, double metres_per_pixel) {
  TexturedPlane plane;
  plane.texture = std::move(texture);
  plane.axes = Eigen::AngleAxisd(yaw_deg * kDeg, Eigen::Vector3d::UnitY()).toRotationMatrix();
  plane.metres_per_pixel = metres_per_pixel;
  return plane;
}

// Texture pixel -> pixel of the camera at T_c_c0: x ~ K (R A + t e3^T) (u, v, 1).
inline Eigen::Matrix3d texture_to_image(const Camera& camera, const TexturedPlane& plane, const SE3d& T_c_c0) {
  Eigen::Matrix3d M = T_c_c0.rotation_matrix() * plane.texture_to_c0();
  M.col(2) += T_c_c0.translation();
  return camera.pinhole_matrix() * M;
}

// The frame seen by an undistorted camera at T_c_c0. warpPerspective samples
// at integer pixel positions = pixel centres, the project's convention.
inline cv::Mat render(const Camera& camera, const TexturedPlane& plane, const SE3d& T_c_c0) {
  cv::Mat H;
  cv::eigen2cv(texture_to_image(camera, plane, T_c_c0), H);
  cv::Mat frame;
  cv::warpPerspective(plane.texture, frame, H, cv::Size(camera.width(), camera.height()), cv::INTER_LINEAR,
                      cv::BORDER_REFLECT);
  return frame;
}

// Where a pixel of the frame at T_a_c0 appears in the frame at T_b_c0.
inline Eigen::Vector2d transfer(const Camera& camera, const TexturedPlane& plane, const SE3d& T_a_c0,
                                const SE3d& T_b_c0, const Eigen::Vector2d& px_a) {
  const Eigen::Matrix3d H = texture_to_image(camera, plane, T_b_c0) * texture_to_image(camera, plane, T_a_c0).inverse();
  return (H * px_a.homogeneous()).hnormalized();
}

// The hand-held start of a session: the camera slides sideways (6 mm per
// frame, a little up and forward) while turning slightly.
inline SE3d sliding_camera(int frame) {
  const double k = frame;
  return second_camera({0.006 * k, 0.0015 * k, 0.002 * k}, {0.03 * kDeg * k, -0.08 * kDeg * k, 0.0});
}

}  // namespace facadeslam::test
