#pragma once
// Synthetic two-view scenes for the initialiser tests: cameras, random 3D
// points (a box of depths or a facade plane) seen by two cameras, pixel
// noise and outlier matches, all from fixed seeds; and the angle errors the
// tests measure.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "core/camera/camera.hpp"
#include "core/lie/se3.hpp"
#include "tests/core/camera/camera_test_util.hpp"

namespace facadeslam::test {

inline constexpr double kDeg = std::numbers::pi / 180.0;

// 640x480 ideal pinhole (configs/camera/synthetic-640x480.yaml).
inline Camera plain_camera() {
  return Camera(640, 480, PinholeRadTan{.fx = 500.0, .fy = 500.0, .cx = 319.5, .cy = 239.5});
}

// OpenCV's sample left camera (configs/camera/opencv-left.yaml): strong
// barrel distortion at the corners.
inline Camera opencv_left_camera() { return Camera(640, 480, opencv_left_model()); }

// PTAM's wide-angle ATAN camera (configs/camera/ptam-atan-example.yaml).
inline Camera atan_camera() { return Camera(640, 480, ptam_example_model()); }

inline Camera camera_by_name(const std::string& name) {
  if (name == "opencv_left") return opencv_left_camera();
  if (name == "atan") return atan_camera();
  return plain_camera();
}

// The second camera, given its centre in the first camera's frame and the
// rotation R_c1_c0 as an axis-angle vector (radians).
inline SE3d second_camera(const Eigen::Vector3d& centre_c0, const Eigen::Vector3d& axis_angle) {
  const SO3<double> R = SO3<double>::exp(axis_angle);
  return SE3d(R, -(R * centre_c0));
}

struct SyntheticMatches {
  std::vector<Eigen::Vector2d> pixels0, pixels1;  // noisy observations
  std::vector<Eigen::Vector3d> points_c0;         // ground truth
  std::vector<bool> outlier;                      // pixels1 replaced by a random pixel
};

enum class SceneShape { box, plane };

// `count` points visible in both views. Each is made from a random pixel of
// camera 0 (5 px from the border) and either a random depth in [2, 6] m
// (box) or the intersection of its ray with a facade plane 4 m away whose
// normal is turned plane_yaw_deg about the vertical axis (plane). Gaussian noise
// of noise_px is added to both pixels; a share outlier_fraction of the
// matches then gets a random second pixel.
inline SyntheticMatches make_matches(const Camera& camera, const SE3d& T_c1_c0, SceneShape shape, int count,
                                     double noise_px, double outlier_fraction, unsigned seed,
                                     double plane_yaw_deg = 20.0) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(5.0, camera.width() - 6.0), v(5.0, camera.height() - 6.0);
  std::uniform_real_distribution<double> depth(2.0, 6.0), unit(0.0, 1.0);
  std::normal_distribution<double> noise(0.0, noise_px);
  const Eigen::Vector3d normal =
      Eigen::AngleAxisd(plane_yaw_deg * kDeg, Eigen::Vector3d::UnitY()) * Eigen::Vector3d::UnitZ();
  const double plane_distance = 4.0;
  SyntheticMatches m;
  int attempts = 0;
  while (static_cast<int>(m.points_c0.size()) < count && ++attempts < 100 * count) {
    // Vectors are filled with <<, which draws in order: as a call's arguments
    // the draws would be in the compiler's order, and the data with them.
    Eigen::Vector2d px0;
    px0 << u(rng), v(rng);
    const Eigen::Vector3d ray = camera.unproject(px0);
    const Eigen::Vector3d p0 = shape == SceneShape::box ? Eigen::Vector3d(ray * depth(rng))
                                                        : Eigen::Vector3d(ray * (plane_distance / normal.dot(ray)));
    const Eigen::Vector3d p1 = T_c1_c0 * p0;
    if (p1.z() <= 0.1) continue;
    const Eigen::Vector2d px1 = camera.project(p1);
    if (!camera.in_image(px1, 5.0)) continue;
    m.points_c0.push_back(p0);
    Eigen::Vector2d noise0, noise1;
    noise0 << noise(rng), noise(rng);
    noise1 << noise(rng), noise(rng);
    m.pixels0.push_back(camera.project(p0) + noise0);
    m.pixels1.push_back(px1 + noise1);
    m.outlier.push_back(false);
  }
  for (std::size_t i = 0; i < m.pixels1.size(); ++i) {
    if (unit(rng) >= outlier_fraction) continue;
    m.pixels1[i] << u(rng), v(rng);
    m.outlier[i] = true;
  }
  return m;
}

inline double rotation_error_deg(const SE3d& estimate, const SE3d& truth) {
  return (estimate.so3().inverse() * truth.so3()).log().norm() / kDeg;
}

inline double direction_error_deg(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return std::atan2(a.cross(b).norm(), a.dot(b)) / kDeg;
}

inline double percentile(std::vector<double> values, double q) {
  if (values.empty()) return 0.0;
  std::sort(values.begin(), values.end());
  return values[static_cast<std::size_t>(q * static_cast<double>(values.size() - 1) + 0.5)];
}

}  // namespace facadeslam::test
