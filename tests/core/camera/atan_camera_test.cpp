#include "core/camera/atan_camera.hpp"

#include <cmath>
#include <numbers>
#include <random>

#include <gtest/gtest.h>

#include "tests/core/camera/camera_test_util.hpp"

namespace facadeslam {
namespace {

using test::ptam_example_model;

TEST(AtanCamera, DistortedRadiusFollowsTheFovFormula) {
  const AtanCamera cam = ptam_example_model(0.93);
  for (double r : {0.05, 0.3, 0.5, 1.0, 2.5}) {
    const Eigen::Vector2d xn(r * 0.6, r * 0.8);  // |xn| = r
    const double expected = std::atan(2.0 * r * std::tan(0.93 / 2.0)) / 0.93;
    EXPECT_NEAR(cam.distort(xn).norm(), expected, 1e-15) << "r = " << r;
    // The direction is kept.
    EXPECT_NEAR(cam.distort(xn).normalized().dot(xn.normalized()), 1.0, 1e-15);
  }
}

TEST(AtanCamera, ZeroWIsPlainPinholeAndSmallWIsContinuous) {
  const AtanCamera pinhole = ptam_example_model(0.0);
  const Eigen::Vector3d p(0.8, -0.5, 2.0);
  const Eigen::Vector2d px = pinhole.project(p);
  EXPECT_DOUBLE_EQ(px.x(), 450 * 0.4 + 319.5);
  EXPECT_DOUBLE_EQ(px.y(), 450 * -0.25 + 239.5);
  EXPECT_EQ(pinhole.unproject(px), Eigen::Vector3d(0.4, -0.25, 1.0));
  for (double w : {1e-12, 1e-8, 1e-5, 1e-4 * 0.999, 1e-4 * 1.001}) {
    // r_d - r = O(w^2 r^3): tiny w must move the pixel by almost nothing.
    EXPECT_LT((ptam_example_model(w).project(p) - px).norm(), 450 * w * w) << "w = " << w;
    EXPECT_LT((ptam_example_model(w).unproject(px) - Eigen::Vector3d(0.4, -0.25, 1.0)).norm(), w * w) << w;
  }
}

TEST(AtanCamera, SeriesAndClosedFormAgreeAtTheirBoundary) {
  const double bound = atan_detail::kSeriesBound;
  for (double u : {bound * (1 - 1e-12), bound * (1 + 1e-12)}) {
    const double s = std::sqrt(u);
    EXPECT_NEAR(atan_detail::atan_sqrt_ratio(u), std::atan(s) / s, 1e-16);
  }
  EXPECT_EQ(atan_detail::atan_sqrt_ratio(0.0), 1.0);
  EXPECT_NEAR(atan_detail::tan_half_ratio(1e-4 * 0.999), 2 * std::tan(0.5e-4 * 0.999) / (1e-4 * 0.999), 1e-15);
  EXPECT_EQ(atan_detail::tan_half_ratio(0.0), 1.0);
}

TEST(AtanCamera, ProjectOfUnprojectIsIdentityOverWholeImage) {
  for (double w : {0.0, 0.5, 0.93, 1.5}) {
    const AtanCamera cam = ptam_example_model(w);
    double worst = 0.0;
    for (int y = 0; y < 480; y += 3)
      for (int x = 0; x < 640; x += 3) {
        const Eigen::Vector2d px(x, y);
        worst = std::max(worst, (cam.project(cam.unproject(px)) - px).norm());
      }
    for (double x : {-0.5, 639.5})
      for (double y : {-0.5, 479.5}) {
        const Eigen::Vector2d px(x, y);
        worst = std::max(worst, (cam.project(cam.unproject(px)) - px).norm());
      }
    EXPECT_LT(worst, 1e-6) << "w = " << w;
    EXPECT_LT(worst, 1e-9) << "w = " << w;
  }
}

TEST(AtanCamera, UnprojectOfProjectRecoversRandomPoints) {
  const AtanCamera cam = ptam_example_model(0.93);
  std::mt19937 rng(17);
  for (int i = 0; i < 2000; ++i) {
    const Eigen::Vector3d p = test::random_point_in_view(rng, 1.2, 0.9);
    const Eigen::Vector3d ray = cam.unproject(cam.project(p));
    EXPECT_LT((ray * p.z() - p).norm(), 1e-10 * p.norm()) << p.transpose();
  }
}

TEST(AtanCamera, PixelsBeyondTheFieldGiveFiniteRays) {
  const AtanCamera cam = ptam_example_model(0.93);
  EXPECT_NEAR(cam.max_distorted_radius(), std::numbers::pi / (2 * 0.93), 1e-15);
  EXPECT_TRUE(std::isinf(ptam_example_model(0.0).max_distorted_radius()));
  // 2 * max radius away from the centre: no real ray exists.
  const Eigen::Vector2d far(cam.cx + 2 * cam.max_distorted_radius() * cam.fx, cam.cy);
  const Eigen::Vector3d ray = cam.unproject(far);
  EXPECT_TRUE(ray.allFinite());
  EXPECT_GT(ray.x(), 1e6);
}

TEST(AtanCamera, ProjectJacobianMatchesCentralDifferences) {
  for (double w : {0.0, 1e-6, 0.93, 2.0}) {
    const AtanCamera cam = ptam_example_model(w);
    std::mt19937 rng(19);
    for (int i = 0; i < 200; ++i) {
      // Include points on and very near the optical axis (r -> 0 limit).
      Eigen::Vector3d p = test::random_point_in_view(rng, 1.0, 0.75);
      if (i == 0) p = Eigen::Vector3d(0, 0, 2);
      if (i == 1) p = Eigen::Vector3d(1e-9, -2e-9, 1);
      const Eigen::Matrix<double, 2, 3> analytic = cam.project_jacobian(p);
      const Eigen::Matrix<double, 2, 3> numeric =
          test::numeric_jacobian([&](const Eigen::Vector3d& q) { return cam.project(q); }, p, 1e-6 * p.z());
      EXPECT_LT((analytic - numeric).norm(), 1e-6 * analytic.norm()) << "w = " << w << " p = " << p.transpose() << "\n"
                                                                     << analytic << "\n"
                                                                     << numeric;
    }
  }
}

TEST(AtanCamera, AutoDiffThroughProjectMatchesAnalyticJacobian) {
  for (double w : {0.0, 0.93}) {
    const AtanCamera cam = ptam_example_model(w);
    std::mt19937 rng(23);
    for (int i = 0; i < 200; ++i) {
      Eigen::Vector3d p = test::random_point_in_view(rng, 1.0, 0.75);
      if (i == 0) p = Eigen::Vector3d(0, 0, 2);  // sqrt(0) would give an infinite derivative
      Eigen::Vector2d value;
      const Eigen::Matrix<double, 2, 3> J = test::autodiff_jacobian(cam, p, &value);
      ASSERT_TRUE(J.allFinite()) << p.transpose();
      EXPECT_LT((value - cam.project(p)).norm(), 1e-12);
      EXPECT_LT((J - cam.project_jacobian(p)).norm(), 1e-10 * J.norm()) << "w = " << w << " p = " << p.transpose();
    }
  }
}

}  // namespace
}  // namespace facadeslam
