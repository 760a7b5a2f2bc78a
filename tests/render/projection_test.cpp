#include <random>

#include <Eigen/Geometry>

#include <gtest/gtest.h>

#include "render/projection.hpp"

namespace facadeslam::render {
namespace {

const PinholeIntrinsics kCamera{640, 480, 520.3, 498.7, 331.2, 228.9};

TEST(Projection, ClipSpaceLandsOnThePixelCameraProjectGives) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> xy(-3.0, 3.0), z(0.5, 40.0);
  const Eigen::Matrix4d clip = clip_from_camera(kCamera, 0.05);
  for (int i = 0; i < 1000; ++i) {
    const Eigen::Vector3d p(xy(rng), xy(rng), z(rng));
    const Eigen::Vector2d expected = kCamera.project(p);
    const Eigen::Vector2d got = pixel_from_clip(kCamera, clip * p.homogeneous());
    ASSERT_NEAR(got.x(), expected.x(), 1e-9);
    ASSERT_NEAR(got.y(), expected.y(), 1e-9);
  }
}

TEST(Projection, PixelZeroIsTheCentreOfTheFirstWindowPixel) {
  // A point projecting to pixel (0, 0) must reach window coordinate
  // (0.5, 0.5), the centre OpenGL samples for the first pixel; the row is not
  // flipped (window row 0 is read back first, as image row 0).
  const Eigen::Matrix4d clip = clip_from_camera(kCamera, 0.05);
  const Eigen::Vector3d p((0.0 - kCamera.cx) / kCamera.fx * 2.0, (0.0 - kCamera.cy) / kCamera.fy * 2.0, 2.0);
  const Eigen::Vector4d c = clip * p.homogeneous();
  EXPECT_NEAR(0.5 * (c.x() / c.w() + 1.0) * kCamera.width, 0.5, 1e-12);
  EXPECT_NEAR(0.5 * (c.y() / c.w() + 1.0) * kCamera.height, 0.5, 1e-12);
}

TEST(Projection, ReversedDepthIsNearOverZ) {
  const double near = 0.05;
  const Eigen::Matrix4d clip = clip_from_camera(kCamera, near);
  for (double z : {near, 1.0, 10.0, 1000.0}) {
    const Eigen::Vector4d c = clip * Eigen::Vector4d(0.3, -0.2, z, 1.0);
    EXPECT_NEAR(c.z() / c.w(), near / z, 1e-15);
  }
}

}  // namespace
}  // namespace facadeslam::render
