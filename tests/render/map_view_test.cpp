// The map view draws each point where the camera model puts it, in its
// colour byte for byte, on the background colour; nearer points hide farther
// ones; the framing keeps the map in the picture whatever a few far points do.
#include "render/map_view.hpp"

#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "core/util/angles.hpp"
#include "core/util/error.hpp"
#include "render/map_view_framing.hpp"
#include "render/map_view_legend.hpp"
#include "tests/render/render_test_scenes.hpp"

namespace facadeslam {
namespace {

using render::MapView;
using render::MapViewCamera;
using render::MapViewContent;
using render::MapViewStyle;

MapViewCamera map_view_camera() {
  MapViewCamera camera;
  camera.intrinsics = {.width = 160, .height = 120, .fx = 100, .fy = 100, .cx = 80, .cy = 60};
  // Not the identity, so that the pose is applied the right way round.
  camera.T_w_c = test::look_at({1.0, -4.0, 0.5}, {0.2, 0.0, 0.1});
  return camera;
}

struct Dot {
  Eigen::Vector2d pixel;  // where its centre must land
  double z;               // depth in the virtual camera
  cv::Vec3b colour;
};

// The world point that the camera sees at `pixel` at depth z.
Eigen::Vector3f world_point(const MapViewCamera& camera, const Dot& dot) {
  const auto& k = camera.intrinsics;
  const Eigen::Vector3d p_c((dot.pixel.x() - k.cx) / k.fx * dot.z, (dot.pixel.y() - k.cy) / k.fy * dot.z, dot.z);
  return (camera.T_w_c * p_c).cast<float>();
}

MapViewContent content_of(const MapViewCamera& camera, const std::vector<Dot>& dots) {
  MapViewContent content;
  for (const Dot& d : dots) {
    content.points_w.push_back(world_point(camera, d));
    content.colours_bgr.push_back(d.colour);
  }
  return content;
}

cv::Vec3b background_of(const MapViewStyle& style) {
  return {static_cast<std::uint8_t>(style.background_bgr[0]), static_cast<std::uint8_t>(style.background_bgr[1]),
          static_cast<std::uint8_t>(style.background_bgr[2])};
}

TEST(MapView, DrawsEachPointAtItsProjectionInItsColourOnTheBackground) {
  const MapViewCamera camera = map_view_camera();
  const std::vector<Dot> dots = {{{30, 20}, 3.0, {10, 200, 30}},
                                 {{120, 40}, 5.0, {250, 0, 128}},
                                 {{75, 95}, 2.0, {0, 0, 0}},
                                 {{140, 100}, 8.0, {200, 200, 200}}};
  MapViewStyle style;
  style.point_size = 5.f;
  style.outline_pixels = 0.f;
  MapView view;
  const cv::Mat image = view.render(content_of(camera, dots), camera, style);
  ASSERT_EQ(image.type(), CV_8UC3);
  ASSERT_EQ(image.size(), cv::Size(160, 120));

  // The model itself: PinholeIntrinsics::project of the camera-frame point.
  for (const Dot& d : dots) {
    const Eigen::Vector3d p_c = camera.T_w_c.inverse() * world_point(camera, d).cast<double>();
    const Eigen::Vector2d uv = camera.intrinsics.project(p_c);
    ASSERT_LT((uv - d.pixel).norm(), 1e-3);
  }
  const cv::Vec3b background = background_of(style);
  for (int y = 0; y < image.rows; ++y)
    for (int x = 0; x < image.cols; ++x) {
      double nearest = 1e9;
      const Dot* dot = nullptr;
      for (const Dot& d : dots) {
        const double distance = (d.pixel - Eigen::Vector2d(x, y)).norm();
        if (distance < nearest) nearest = distance, dot = &d;
      }
      // A dot of diameter 5 is the colour within 1 px of its centre and
      // cannot reach farther than its radius plus one pixel.
      if (nearest <= 1.0) {
        ASSERT_EQ(image.at<cv::Vec3b>(y, x), dot->colour) << x << "," << y;
      }
      if (nearest >= 2.5 + 1.0) {
        ASSERT_EQ(image.at<cv::Vec3b>(y, x), background) << x << "," << y;
      }
    }
}

TEST(MapView, OutlinesDotsWithADarkerRingAroundTheExactColour) {
  const MapViewCamera camera = map_view_camera();
  MapViewStyle style;
  style.point_size = 9.f;
  style.outline_pixels = 2.f;
  MapView view;
  const cv::Mat image = view.render(content_of(camera, {{{80, 60}, 4.0, {100, 180, 240}}}), camera, style);
  EXPECT_EQ(image.at<cv::Vec3b>(60, 80), cv::Vec3b(100, 180, 240));
  EXPECT_EQ(image.at<cv::Vec3b>(60, 81), cv::Vec3b(100, 180, 240));
  const cv::Vec3b ring = image.at<cv::Vec3b>(60, 84);  // 4 px out: inside the radius, in the outline
  EXPECT_NEAR(ring[0], 55, 1);
  EXPECT_NEAR(ring[2], 132, 1);
}

TEST(MapView, NearerPointsHideFartherOnesAndPointsBehindAreNotDrawn) {
  const MapViewCamera camera = map_view_camera();
  MapViewStyle style;
  style.point_size = 7.f;
  style.outline_pixels = 0.f;
  // Drawn far first, then near, then far again: only depth decides.
  MapViewContent content =
      content_of(camera, {{{50, 50}, 6.0, {255, 0, 0}}, {{50, 50}, 3.0, {0, 255, 0}}, {{50, 50}, 9.0, {0, 0, 255}}});
  // A point behind the camera that would project into the picture.
  content.points_w.push_back((camera.T_w_c * Eigen::Vector3d(0.1, 0.1, -2.0)).cast<float>());
  content.colours_bgr.emplace_back(1, 2, 3);
  MapView view;
  const cv::Mat image = view.render(content, camera, style);
  EXPECT_EQ(image.at<cv::Vec3b>(50, 50), cv::Vec3b(0, 255, 0));
  EXPECT_EQ(cv::countNonZero(image.reshape(1) == 1), 0);
}

TEST(MapView, DrawsTheTrajectoryAndKeyframesAsLines) {
  const MapViewCamera camera = map_view_camera();
  MapViewStyle style;
  style.trajectory_line_width = 1.f;
  MapViewContent content;
  const auto at = [&](double u, double v, double z) {
    return world_point(camera, {{u, v}, z, {}}).cast<double>().eval();
  };
  content.trajectory_w = {at(20, 30, 3.0), at(100, 30, 3.0), at(100, 90, 3.0)};
  MapView view;
  const cv::Mat image = view.render(content, camera, style);
  // The middle of each segment (a horizontal and a vertical one, so the
  // rasterised line has exactly these pixels on it).
  EXPECT_EQ(image.at<cv::Vec3b>(30, 60), style.trajectory_bgr);
  EXPECT_EQ(image.at<cv::Vec3b>(60, 100), style.trajectory_bgr);
  EXPECT_EQ(image.at<cv::Vec3b>(60, 60), background_of(style));

  // A keyframe 2 m in front of the view, looking the same way: its pyramid's
  // apex projects to the principal point and its base lies around it.
  content.trajectory_w.clear();
  Eigen::Isometry3d T_w_kf = camera.T_w_c;
  T_w_kf.translation() = camera.T_w_c * Eigen::Vector3d(0, 0, 2.0);
  content.keyframes_T_c_w = {T_w_kf.inverse()};
  style.frustum_depth = 1.0;
  const cv::Mat pyramid = view.render(content, camera, style);
  // The middle of the base's lower edge, (0, 0.45, 1) in the keyframe, is
  // at depth 3 in the view: pixel (80, 75).
  const Eigen::Vector2d edge = camera.intrinsics.project({0.0, 0.45, 3.0});
  ASSERT_LT((edge - Eigen::Vector2d(80, 75)).norm(), 1e-9);
  EXPECT_EQ(pyramid.at<cv::Vec3b>(75, 80), style.keyframe_bgr);
  EXPECT_EQ(pyramid.at<cv::Vec3b>(5, 5), background_of(style));
}

TEST(MapView, LegendChangesOnlyItsBox) {
  const MapViewCamera camera = map_view_camera();
  MapViewContent content = content_of(camera, {{{30, 20}, 3.0, {10, 200, 30}}, {{120, 90}, 3.0, {0, 0, 128}}});
  MapView view;
  const cv::Mat plain = view.render(content, camera);
  content.legend = {{"building (2)", {0, 0, 128}, false}, {"trajectory", {0, 140, 255}, true}};
  const cv::Mat with_legend = view.render(content, camera);
  const cv::Rect box = render::legend_box(plain.size(), content.legend);
  ASSERT_FALSE(box.empty());
  const cv::Mat channels_differ = plain != with_legend;
  cv::Mat differs;
  cv::reduce(channels_differ.reshape(1, plain.rows * plain.cols), differs, 1, cv::REDUCE_MAX);
  differs = differs.reshape(1, plain.rows);
  EXPECT_GT(cv::countNonZero(differs(box)), 0);
  EXPECT_EQ(cv::countNonZero(differs) - cv::countNonZero(differs(box)), 0);
}

TEST(MapView, RejectsMismatchedColoursAndSizes) {
  MapViewCamera camera = map_view_camera();
  MapViewContent content;
  content.points_w = {Eigen::Vector3f::Zero()};
  MapView view;
  EXPECT_THROW(view.render(content, camera), Error);
  content.colours_bgr.push_back(cv::Vec3b::all(0));
  camera.intrinsics.width = 8;
  EXPECT_THROW(view.render(content, camera), Error);
}

// Upright cameras looking along world +x (their y axis is world -z).
std::vector<Eigen::Isometry3d> cameras_looking_along_x() {
  std::vector<Eigen::Isometry3d> T_c_w;
  for (int i = 0; i < 3; ++i)
    T_c_w.push_back(test::look_at({0.0, i * 1.0, 0.0}, {1.0, i * 1.0, 0.0}, Eigen::Vector3d::UnitZ()).inverse());
  return T_c_w;
}

TEST(MapViewFraming, UpAndForwardComeFromTheCameras) {
  const render::ViewAxes axes = render::view_axes_from_cameras(cameras_looking_along_x());
  EXPECT_LT((axes.up_w - Eigen::Vector3d::UnitZ()).norm(), 1e-9);
  EXPECT_LT((axes.forward_w - Eigen::Vector3d::UnitX()).norm(), 1e-9);
  const render::ViewAxes none = render::view_axes_from_cameras({});
  EXPECT_EQ(none.up_w, -Eigen::Vector3d::UnitY());
}

// A street: 2000 points in a 10 x 4 x 3 box, plus 1 % far away.
std::vector<Eigen::Vector3f> street_with_outliers() {
  std::mt19937 random(7);
  std::uniform_real_distribution<float> x(0, 10), y(-2, 2), z(0, 3), far(-500, 500);
  std::vector<Eigen::Vector3f> points;
  for (int i = 0; i < 2000; ++i) points.emplace_back(x(random), y(random), z(random));
  for (int i = 0; i < 20; ++i) points.emplace_back(far(random), far(random), far(random));
  return points;
}

TEST(MapViewFraming, FillsThePictureWithTheMapDespiteFarOutliers) {
  const auto points = street_with_outliers();
  const render::ViewAxes axes = render::view_axes_from_cameras(cameras_looking_along_x());
  for (const auto kind : {render::MapViewKind::oblique, render::MapViewKind::top}) {
    const render::MapViewFraming framing = render::frame_map_view(points, {}, axes, kind, 640, 360);
    const MapViewCamera& camera = framing.camera;
    const Eigen::Isometry3d T_c_w = camera.T_w_c.inverse();
    double u_lo = 1e9, u_hi = -1e9, v_lo = 1e9, v_hi = -1e9;
    int inside = 0;
    for (std::size_t i = 0; i < 2000; ++i) {
      const Eigen::Vector3d p_c = T_c_w * points[i].cast<double>();
      ASSERT_GT(p_c.z(), camera.near);
      const Eigen::Vector2d uv = camera.intrinsics.project(p_c);
      inside += uv.x() >= 0 && uv.x() <= 639 && uv.y() >= 0 && uv.y() <= 359;
      u_lo = std::min(u_lo, uv.x()), u_hi = std::max(u_hi, uv.x());
      v_lo = std::min(v_lo, uv.y()), v_hi = std::max(v_hi, uv.y());
    }
    // Nearly all of the street is in the picture (2-98 % per axis, so a few
    // of its own extreme points may fall just outside) ...
    EXPECT_GE(inside, 1900);
    // ... and fills it: the far points did not shrink it.
    EXPECT_GT(std::max((u_hi - u_lo) / 640, (v_hi - v_lo) / 360), 0.85);
    EXPECT_LT(framing.box_diagonal, 12.0);
  }
}

TEST(MapViewFraming, TopLooksDownAlongTheMapObliqueFromBehindAndAbove) {
  const auto points = street_with_outliers();
  const render::ViewAxes axes = render::view_axes_from_cameras(cameras_looking_along_x());
  const auto top = render::frame_map_view(points, {}, axes, render::MapViewKind::top, 640, 360).camera;
  EXPECT_LT((top.T_w_c.linear().col(2) + Eigen::Vector3d::UnitZ()).norm(), 1e-9);  // optical axis down
  // The street (along x) runs across the landscape picture.
  EXPECT_GT(std::abs(top.T_w_c.linear().col(0).x()), 0.99);

  const auto oblique = render::frame_map_view(points, {}, axes, render::MapViewKind::oblique, 640, 360).camera;
  const Eigen::Vector3d centre = oblique.T_w_c.translation(), axis = oblique.T_w_c.linear().col(2);
  EXPECT_LT(centre.x(), 0.0);  // behind the street's start
  EXPECT_GT(centre.z(), 3.0);  // above its top
  EXPECT_NEAR(rad_to_deg(std::asin(-axis.z())), 35.0, 1e-6);
}

TEST(MapViewFraming, AnchorsAreAlwaysInThePicture) {
  const auto points = street_with_outliers();
  const std::vector<Eigen::Vector3d> anchors = {{-6, 0, 1.5}, {14, 1, 1.5}};
  const auto camera = render::frame_map_view(points, anchors, render::view_axes_from_cameras(cameras_looking_along_x()),
                                             render::MapViewKind::top, 320, 240)
                          .camera;
  for (const auto& a : anchors) {
    const Eigen::Vector2d uv = camera.intrinsics.project(camera.T_w_c.inverse() * a);
    EXPECT_TRUE(uv.x() >= 0 && uv.x() <= 319 && uv.y() >= 0 && uv.y() <= 239) << uv.transpose();
  }
}

}  // namespace
}  // namespace facadeslam
