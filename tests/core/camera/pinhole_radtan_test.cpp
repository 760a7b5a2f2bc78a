#include "core/camera/pinhole_radtan.hpp"

#include <random>
#include <vector>

#include <gtest/gtest.h>
#include <opencv2/calib3d.hpp>

#include "tests/core/camera/camera_test_util.hpp"

namespace facadeslam {
namespace {

using test::opencv_left_model;

// Pixels every `step` over the whole 640x480 image, its last row and column
// and the outer corners of the pixel area.
std::vector<Eigen::Vector2d> dense_grid(int width, int height, int step) {
  std::vector<Eigen::Vector2d> pixels;
  for (int y = 0; y < height; y += step)
    for (int x = 0; x < width; x += step) pixels.emplace_back(x, y);
  for (int x = 0; x < width; ++x) pixels.emplace_back(x, height - 1);
  for (int y = 0; y < height; ++y) pixels.emplace_back(width - 1, y);
  for (double x : {-0.5, width - 0.5})
    for (double y : {-0.5, height - 0.5}) pixels.emplace_back(x, y);
  return pixels;
}

TEST(PinholeRadTan, ProjectOfUnprojectIsIdentityOverWholeDistortedImage) {
  const PinholeRadTan cam = opencv_left_model();
  double worst = 0.0;
  for (const Eigen::Vector2d& px : dense_grid(640, 480, 4)) {
    const Eigen::Vector3d ray = cam.unproject(px);
    EXPECT_EQ(ray(2), 1.0);
    worst = std::max(worst, (cam.project(ray) - px).norm());
  }
  EXPECT_LT(worst, 1e-6) << "worst round-trip error in pixels";
  // Newton runs to rounding level, far below the required 1e-6.
  EXPECT_LT(worst, 1e-9);
}

TEST(PinholeRadTan, UnprojectOfProjectRecoversRandomPoints) {
  const PinholeRadTan cam = opencv_left_model();
  std::mt19937 rng(7);
  for (int i = 0; i < 2000; ++i) {
    const Eigen::Vector3d p = test::random_point_in_view(rng, 0.65, 0.5);
    const Eigen::Vector3d ray = cam.unproject(cam.project(p));
    EXPECT_LT((ray * p.z() - p).norm(), 1e-10 * p.norm()) << p.transpose();
  }
}

TEST(PinholeRadTan, UndistortInvertsDistortAtCornersWhereOpenCvsFixedIterationsFallShort) {
  const PinholeRadTan cam = opencv_left_model();
  // The top-left corner: the longest distorted radius of this image.
  const Eigen::Vector2d xd((-0.5 - cam.cx) / cam.fx, (-0.5 - cam.cy) / cam.fy);
  const Eigen::Vector2d xn = cam.undistort(xd);
  EXPECT_LT((cam.distort(xn) - xd).norm(), 1e-14);
  EXPECT_GT(xn.norm(), xd.norm()) << "barrel distortion pulls the corner inwards";

  // OpenCV's undistortPoints (5 fixed-point iterations by default) is
  // measurably off there, which is why unproject does not use it.
  const cv::Matx33d K(cam.fx, 0, cam.cx, 0, cam.fy, cam.cy, 0, 0, 1);
  const std::vector<double> dist{cam.k1, cam.k2, cam.p1, cam.p2, cam.k3};
  std::vector<cv::Point2d> in{{-0.5, -0.5}}, out;
  cv::undistortPoints(in, out, K, dist);
  const double opencv_error = (Eigen::Vector2d(out[0].x, out[0].y) - xn).norm() * cam.fx;
  EXPECT_GT(opencv_error, 1e-3) << "pixels";
}

TEST(PinholeRadTan, AgreesWithCvProjectPoints) {
  const PinholeRadTan cam = opencv_left_model();
  std::mt19937 rng(11);
  std::vector<cv::Point3d> points;
  for (int i = 0; i < 1000; ++i) {
    const Eigen::Vector3d p = test::random_point_in_view(rng, 0.8, 0.6);
    points.emplace_back(p.x(), p.y(), p.z());
  }
  const cv::Matx33d K(cam.fx, 0, cam.cx, 0, cam.fy, cam.cy, 0, 0, 1);
  const std::vector<double> dist{cam.k1, cam.k2, cam.p1, cam.p2, cam.k3};
  std::vector<cv::Point2d> expected;
  cv::projectPoints(points, cv::Vec3d(0, 0, 0), cv::Vec3d(0, 0, 0), K, dist, expected);
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Eigen::Vector2d px = cam.project(Eigen::Vector3d(points[i].x, points[i].y, points[i].z));
    EXPECT_NEAR(px.x(), expected[i].x, 1e-6);
    EXPECT_NEAR(px.y(), expected[i].y, 1e-6);
  }
}

TEST(PinholeRadTan, WithoutDistortionIsPlainPinhole) {
  const PinholeRadTan cam{.fx = 500, .fy = 480, .cx = 319.5, .cy = 239.5};
  EXPECT_FALSE(cam.has_distortion());
  EXPECT_TRUE(opencv_left_model().has_distortion());
  const Eigen::Vector3d p(0.4, -0.3, 2.0);
  const Eigen::Vector2d px = cam.project(p);
  EXPECT_DOUBLE_EQ(px.x(), 500 * 0.2 + 319.5);
  EXPECT_DOUBLE_EQ(px.y(), 480 * -0.15 + 239.5);
  const Eigen::Vector3d ray = cam.unproject(px);
  EXPECT_NEAR(ray.x(), 0.2, 1e-15);
  EXPECT_NEAR(ray.y(), -0.15, 1e-15);
}

TEST(PinholeRadTan, ProjectJacobianMatchesCentralDifferences) {
  const PinholeRadTan cam = opencv_left_model();
  std::mt19937 rng(3);
  for (int i = 0; i < 200; ++i) {
    const Eigen::Vector3d p = test::random_point_in_view(rng, 0.7, 0.55);
    const Eigen::Matrix<double, 2, 3> analytic = cam.project_jacobian(p);
    const Eigen::Matrix<double, 2, 3> numeric =
        test::numeric_jacobian([&](const Eigen::Vector3d& q) { return cam.project(q); }, p, 1e-6 * p.z());
    EXPECT_LT((analytic - numeric).norm(), 1e-6 * analytic.norm()) << "\n" << analytic << "\n" << numeric;
  }
}

TEST(PinholeRadTan, DistortJacobianMatchesCentralDifferences) {
  const PinholeRadTan cam = opencv_left_model();
  for (const Eigen::Vector2d& xn :
       {Eigen::Vector2d(0.0, 0.0), Eigen::Vector2d(0.5, -0.4), Eigen::Vector2d(-0.7, 0.6)}) {
    const double h = 1e-7;
    Eigen::Matrix2d numeric;
    for (int i = 0; i < 2; ++i) {
      Eigen::Vector2d plus = xn, minus = xn;
      plus(i) += h;
      minus(i) -= h;
      numeric.col(i) = (cam.distort(plus) - cam.distort(minus)) / (2 * h);
    }
    EXPECT_LT((cam.distort_jacobian(xn) - numeric).norm(), 1e-7);
  }
}

TEST(PinholeRadTan, AutoDiffThroughProjectMatchesAnalyticJacobian) {
  const PinholeRadTan cam = opencv_left_model();
  std::mt19937 rng(5);
  for (int i = 0; i < 200; ++i) {
    const Eigen::Vector3d p = test::random_point_in_view(rng, 0.7, 0.55);
    Eigen::Vector2d value;
    const Eigen::Matrix<double, 2, 3> J = test::autodiff_jacobian(cam, p, &value);
    EXPECT_LT((value - cam.project(p)).norm(), 1e-12);
    EXPECT_LT((J - cam.project_jacobian(p)).norm(), 1e-10 * J.norm());
  }
}

}  // namespace
}  // namespace facadeslam
