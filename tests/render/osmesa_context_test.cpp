// The OSMesa context really renders: a wrong link order (libGL before
// OSMesa) gives a NULL GL_RENDERER and black images without any error, so
// these tests check the strings and actual pixel values.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "core/util/error.hpp"
#include "render/offscreen_renderer.hpp"
#include "tests/render/render_test_scenes.hpp"

namespace facadeslam {
namespace {

using render::kTransparentLabel;
using render::make_textured_quad;
using render::Renderer;
using render::Scene;
using render::TextureId;

Camera test_camera() { return Camera(64, 48, PinholeRadTan{.fx = 50, .fy = 50, .cx = 31.5, .cy = 23.5}); }

// A wall at z = depth in front of the identity camera, larger than the view.
render::Mesh wall(TextureId colour, TextureId labels, std::uint8_t label, double depth) {
  return make_textured_quad({-10, -10, depth}, {20, 0, 0}, {0, 20, 0}, colour, labels, label);
}

TEST(OsMesaContext, ReportsAnOpenGl45CoreRenderer) {
  Renderer renderer;
  EXPECT_FALSE(renderer.gl_renderer().empty()) << "GL_RENDERER is NULL: is libGL linked before OSMesa?";
  EXPECT_THAT(renderer.gl_version(), ::testing::StartsWith("4.5"));
  EXPECT_GE(renderer.max_texture_size(), 8192);
}

TEST(OsMesaContext, DrawsTextureColourConstantLabelAndDepth) {
  Renderer renderer;
  const TextureId colour = renderer.add_colour_texture(cv::Mat(8, 8, CV_8UC3, cv::Scalar(40, 120, 200)));
  Scene scene;
  scene.meshes.push_back(wall(colour, {}, 3, 4.0));
  const auto out = renderer.render(scene, test_camera(), Eigen::Isometry3d::Identity());
  ASSERT_EQ(out.colour.type(), CV_32FC3);
  for (int y = 0; y < out.colour.rows; ++y)
    for (int x = 0; x < out.colour.cols; ++x) {
      const cv::Vec3f c = out.colour.at<cv::Vec3f>(y, x);
      ASSERT_NEAR(c[0], 40.f, 0.01f);  // BGR order preserved
      ASSERT_NEAR(c[1], 120.f, 0.01f);
      ASSERT_NEAR(c[2], 200.f, 0.01f);
      ASSERT_EQ(out.labels.at<std::uint8_t>(y, x), 3);
      ASSERT_NEAR(out.depth.at<float>(y, x), 4.f, 1e-5f);
    }
}

TEST(OsMesaContext, BackgroundWhereNothingIsDrawn) {
  Renderer renderer;
  Scene scene;
  scene.background_colour = cv::Scalar(10, 20, 30);
  scene.background_label = 7;
  const auto out = renderer.render(scene, test_camera(), Eigen::Isometry3d::Identity());
  EXPECT_EQ(out.colour.at<cv::Vec3f>(10, 10), cv::Vec3f(10, 20, 30));
  EXPECT_EQ(cv::countNonZero(out.labels != 7), 0);
  EXPECT_EQ(cv::countNonZero(out.depth), 0);
}

TEST(OsMesaContext, ReadsBackOnlyTheRequestedLayers) {
  Renderer renderer;
  const auto out = renderer.render(Scene{}, test_camera(), Eigen::Isometry3d::Identity(), render::kLabels);
  EXPECT_TRUE(out.colour.empty());
  EXPECT_FALSE(out.labels.empty());
  EXPECT_TRUE(out.depth.empty());
}

TEST(OsMesaContext, NearerSurfaceWinsWhateverTheDrawingOrder) {
  Renderer renderer;
  const TextureId grey = renderer.add_colour_texture(cv::Mat(4, 4, CV_8UC1, cv::Scalar(128)));
  for (bool near_first : {true, false}) {
    Scene scene;
    scene.meshes.push_back(wall(grey, {}, near_first ? 1 : 2, near_first ? 3.0 : 3.001));
    scene.meshes.push_back(wall(grey, {}, near_first ? 2 : 1, near_first ? 3.001 : 3.0));
    const auto out = renderer.render(scene, test_camera(), Eigen::Isometry3d::Identity());
    EXPECT_EQ(cv::countNonZero(out.labels != 1), 0) << (near_first ? "near first" : "far first");
  }
}

TEST(OsMesaContext, TransparentLabelTexelsAreHoles) {
  Renderer renderer;
  const TextureId white = renderer.add_colour_texture(cv::Mat(2, 2, CV_8UC1, cv::Scalar(255)));
  cv::Mat labels(2, 2, CV_8UC1, cv::Scalar(5));
  labels.col(0).setTo(kTransparentLabel);  // left half of the wall missing
  Scene scene;
  scene.background_label = 9;
  scene.meshes.push_back(wall(white, renderer.add_label_texture(labels), 0, 2.0));
  const auto out = renderer.render(scene, test_camera(), Eigen::Isometry3d::Identity());
  // The wall spans x in [-10, 10] at z = 2, so its middle (x = 0) projects to
  // u = cx = 31.5: columns 0..31 see the hole, 32..63 the wall.
  for (int x = 0; x < 64; ++x) {
    const bool hole = x <= 31;
    EXPECT_EQ(out.labels.at<std::uint8_t>(20, x), hole ? 9 : 5) << "column " << x;
    EXPECT_EQ(out.depth.at<float>(20, x), hole ? 0.f : 2.f) << "column " << x;
  }
}

TEST(OsMesaContext, SkyIsLookedUpByDirectionAndIgnoresTranslation) {
  Renderer renderer;
  // Upper half of the panorama (above the horizon) blue-ish, lower half brown.
  cv::Mat panorama(64, 128, CV_8UC3, cv::Scalar(200, 150, 90));
  panorama.rowRange(32, 64).setTo(cv::Scalar(30, 60, 90));
  Scene scene;
  scene.sky = render::Sky{renderer.add_colour_texture(panorama, true), Eigen::Matrix3d::Identity(), 6};
  const Eigen::Isometry3d level = test::look_at({0, 0, 0}, {1, 0, 0});  // horizontal, along world x
  const auto out = renderer.render(scene, test_camera(), level);
  EXPECT_EQ(cv::countNonZero(out.labels != 6), 0);
  EXPECT_EQ(cv::countNonZero(out.depth), 0);
  EXPECT_NEAR(out.colour.at<cv::Vec3f>(2, 30)[0], 200.f, 1.f);  // looking up
  EXPECT_NEAR(out.colour.at<cv::Vec3f>(45, 30)[0], 30.f, 1.f);  // looking down
  Eigen::Isometry3d moved = level;
  moved.translation() = Eigen::Vector3d(50, -20, 7);
  const auto elsewhere = renderer.render(scene, test_camera(), moved);
  EXPECT_EQ(cv::norm(out.colour, elsewhere.colour, cv::NORM_INF), 0.0);
}

TEST(OsMesaContext, RejectsTexturesItDoesNotHold) {
  Renderer renderer;
  Scene scene;
  scene.meshes.push_back(wall(TextureId{42}, {}, 0, 2.0));
  EXPECT_THROW(renderer.render(scene, test_camera(), Eigen::Isometry3d::Identity()), Error);
  const TextureId labels = renderer.add_label_texture(cv::Mat(2, 2, CV_8UC1, cv::Scalar(1)));
  scene.meshes[0].colour = labels;  // a label texture used as colour
  EXPECT_THROW(renderer.render(scene, test_camera(), Eigen::Isometry3d::Identity()), Error);
  EXPECT_THROW(renderer.add_colour_texture(cv::Mat(2, 2, CV_32FC3)), Error);
  EXPECT_THROW(renderer.add_label_texture(cv::Mat(2, 2, CV_8UC3)), Error);
}

}  // namespace
}  // namespace facadeslam
