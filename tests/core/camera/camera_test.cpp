#include "core/camera/camera.hpp"
#include "core/image/half_sample.hpp"

#include <cmath>
#include <random>
#include <type_traits>

#include <Eigen/Geometry>
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

#include "tests/core/camera/camera_test_util.hpp"

namespace facadeslam {
namespace {

using test::error_of;
using ::testing::HasSubstr;

Camera opencv_left() { return Camera(640, 480, test::opencv_left_model()); }
Camera ptam_example() { return Camera(640, 480, test::ptam_example_model()); }

TEST(Camera, DispatchesToItsModel) {
  const PinholeRadTan pinhole = test::opencv_left_model();
  const AtanCamera atan_model = test::ptam_example_model();
  const Camera a(640, 480, pinhole), b(640, 480, atan_model);
  EXPECT_EQ(a.model_name(), "pinhole");
  EXPECT_EQ(b.model_name(), "atan");
  const Eigen::Vector3d p(0.3, -0.2, 1.5);
  const Eigen::Vector2d px(100.0, 400.0);
  EXPECT_EQ(a.project(p), pinhole.project(p));
  EXPECT_EQ(b.project(p), atan_model.project(p));
  EXPECT_EQ(a.unproject(px), pinhole.unproject(px));
  EXPECT_EQ(b.unproject(px), atan_model.unproject(px));
  EXPECT_EQ(a.project_jacobian(p), pinhole.project_jacobian(p));
  EXPECT_EQ(b.project_jacobian(p), atan_model.project_jacobian(p));
  EXPECT_EQ(a.fx(), pinhole.fx);
  EXPECT_EQ(b.cy(), atan_model.cy);
  EXPECT_TRUE(std::holds_alternative<AtanCamera>(b.model()));
}

// K maps a ray on z = 1 to the pixel an undistorted camera would give.
TEST(Camera, PinholeMatrixIsTheLinearPart) {
  const Camera camera(640, 480, PinholeRadTan{.fx = 500.0, .fy = 480.0, .cx = 319.5, .cy = 239.5});
  const Eigen::Vector3d ray(0.2, -0.1, 1.0);
  EXPECT_TRUE((camera.pinhole_matrix() * ray).hnormalized().isApprox(camera.project(ray)));
  const Eigen::Matrix3d K = ptam_example().pinhole_matrix();
  EXPECT_EQ(K(0, 0), 450.0);
  EXPECT_EQ(K(1, 2), 239.5);
  EXPECT_EQ(K.row(2), Eigen::RowVector3d(0, 0, 1));
}

TEST(Camera, VisitGivesTheConcreteModelForAutoDiff) {
  // As bundle adjustment does: one templated functor per concrete model.
  for (const Camera& camera : {opencv_left(), ptam_example()}) {
    const Eigen::Vector3d p(-0.4, 0.25, 3.0);
    const Eigen::Matrix<double, 2, 3> J =
        camera.visit([&](const auto& model) { return test::autodiff_jacobian(model, p); });
    EXPECT_LT((J - camera.project_jacobian(p)).norm(), 1e-10 * J.norm()) << camera.model_name();
  }
}

TEST(Camera, InImageUsesPixelCentresAndBorder) {
  const Camera camera = opencv_left();
  EXPECT_TRUE(camera.in_image({0.0, 0.0}));
  EXPECT_TRUE(camera.in_image({639.0, 479.0}));
  EXPECT_FALSE(camera.in_image({-0.01, 10.0}));
  EXPECT_FALSE(camera.in_image({10.0, -0.01}));
  EXPECT_FALSE(camera.in_image({639.01, 10.0}));
  EXPECT_FALSE(camera.in_image({10.0, 479.01}));
  EXPECT_TRUE(camera.in_image({5.0, 474.0}, 5.0));
  EXPECT_FALSE(camera.in_image({4.9, 200.0}, 5.0));
  EXPECT_FALSE(camera.in_image({200.0, 474.1}, 5.0));
}

TEST(Camera, ScaledToLevelFollowsThePyramidConvention) {
  std::mt19937 rng(29);
  for (const Camera& camera : {opencv_left(), ptam_example()}) {
    for (int level = 0; level <= 4; ++level) {
      const Camera scaled = camera.scaled_to_level(level);
      const double s = std::pow(2.0, level);
      EXPECT_EQ(scaled.model_name(), camera.model_name());
      EXPECT_DOUBLE_EQ(scaled.fx(), camera.fx() / s);
      EXPECT_DOUBLE_EQ(scaled.cx(), (camera.cx() + 0.5) / s - 0.5);
      for (int i = 0; i < 100; ++i) {
        const Eigen::Vector3d p = test::random_point_in_view(rng, 0.6, 0.45);
        const Eigen::Vector2d x0 = camera.project(p);
        const Eigen::Vector2d expected = ((x0.array() + 0.5) / s - 0.5).matrix();
        EXPECT_LT((scaled.project(p) - expected).norm(), 1e-9) << "level " << level;
        // And back: the level-l pixel unprojects to the same ray.
        EXPECT_LT((scaled.unproject(expected) - camera.unproject(x0)).norm(), 1e-9);
      }
    }
  }
}

TEST(Camera, ScaledToLevelHalvesSizesLikeThePyramid) {
  const Camera camera(641, 479, test::opencv_left_model());
  cv::Mat image(camera.height(), camera.width(), CV_8UC1, cv::Scalar(0));
  for (int level = 1; level <= 4; ++level) {
    image = half_sample(image);
    const Camera scaled = camera.scaled_to_level(level);
    EXPECT_EQ(scaled.width(), image.cols) << "level " << level;
    EXPECT_EQ(scaled.height(), image.rows) << "level " << level;
  }
  EXPECT_EQ(camera.scaled_to_level(0).width(), 641);
  EXPECT_THAT(error_of([&] { (void)camera.scaled_to_level(-1); }), HasSubstr("level"));
}

TEST(Camera, ResizedKeepsPixelCentreConvention) {
  const Camera camera = ptam_example();
  const Camera resized = camera.resized(320, 360);  // x by 0.5, y by 0.75
  EXPECT_EQ(resized.width(), 320);
  EXPECT_EQ(resized.height(), 360);
  const Eigen::Vector3d p(0.5, -0.3, 2.0);
  const Eigen::Vector2d x0 = camera.project(p);
  const Eigen::Vector2d expected((x0.x() + 0.5) * 0.5 - 0.5, (x0.y() + 0.5) * 0.75 - 0.5);
  EXPECT_LT((resized.project(p) - expected).norm(), 1e-12);
  EXPECT_THAT(error_of([&] { (void)camera.resized(0, 10); }), HasSubstr("resize"));
}

TEST(Camera, OpenCvMatricesForPinhole) {
  const Camera camera = opencv_left();
  const cv::Mat K = camera.K();
  ASSERT_EQ(K.type(), CV_64F);
  ASSERT_EQ(K.size(), cv::Size(3, 3));
  EXPECT_EQ(K.at<double>(0, 0), camera.fx());
  EXPECT_EQ(K.at<double>(1, 1), camera.fy());
  EXPECT_EQ(K.at<double>(0, 2), camera.cx());
  EXPECT_EQ(K.at<double>(1, 2), camera.cy());
  EXPECT_EQ(K.at<double>(0, 1), 0.0);
  EXPECT_EQ(K.at<double>(2, 2), 1.0);
  const cv::Mat d = camera.distortion();
  ASSERT_EQ(d.total(), 5u);
  EXPECT_EQ(d.at<double>(0), test::opencv_left_model().k1);
  EXPECT_EQ(d.at<double>(3), test::opencv_left_model().p2);
  EXPECT_EQ(d.at<double>(4), test::opencv_left_model().k3);
}

TEST(Camera, AtanHasKButNoOpenCvDistortion) {
  const Camera camera = ptam_example();
  EXPECT_EQ(camera.K().at<double>(0, 2), 319.5);
  EXPECT_THAT(error_of([&] { (void)camera.distortion(); }), HasSubstr("atan"));
}

TEST(Camera, ConstructorRejectsInvalidCameras) {
  EXPECT_THAT(error_of([] { Camera(0, 480, PinholeRadTan{.fx = 500, .fy = 500}); }), HasSubstr("size"));
  EXPECT_THAT(error_of([] { Camera(640, 480, PinholeRadTan{.fx = -1, .fy = 500}); }), HasSubstr("focal"));
  EXPECT_THAT(error_of([] { Camera(640, 480, PinholeRadTan{.fx = 500, .fy = NAN}); }), HasSubstr("focal"));
  EXPECT_THAT(error_of([] { Camera(640, 480, PinholeRadTan{.fx = 500, .fy = 500, .k1 = INFINITY}); }),
              HasSubstr("distortion"));
  EXPECT_THAT(error_of([] { Camera(640, 480, AtanCamera{.fx = 500, .fy = 500, .w = 3.5}); }), HasSubstr("w"));
  EXPECT_THAT(error_of([] { Camera(640, 480, AtanCamera{.fx = 500, .fy = 500, .w = -0.1}); }), HasSubstr("w"));
}

}  // namespace
}  // namespace facadeslam
