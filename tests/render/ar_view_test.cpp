// The augmented view (render/ar/ar_view.hpp) against the camera model:
// the virtual object's corners and the measured points land where
// Camera::project() puts them, for a pinhole, a distorted pinhole and an
// ATAN camera; the object stays anchored in the world over a sequence of
// poses; a frame without a pose or without a map is the image untouched.
#include <algorithm>
#include <cmath>
#include <iostream>
#include <string>

#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

#include "core/util/error.hpp"
#include "render/ar/ar_view.hpp"
#include "render/ar/plane_finder.hpp"
#include "render/ar/virtual_object.hpp"
#include "tests/render/render_test_scenes.hpp"

namespace facadeslam {
namespace {

using render::ar::ArFrameContent;
using render::ar::ArView;
using render::ar::VirtualObject;

struct CameraCase {
  std::string name;
  Camera camera;
};

std::vector<CameraCase> cameras() {
  return {
      {"pinhole", Camera(640, 480, PinholeRadTan{.fx = 520.3, .fy = 498.7, .cx = 331.2, .cy = 228.9})},
      {"radial_tangential",
       Camera(
           640, 480,
           PinholeRadTan{
               .fx = 480, .fy = 482, .cx = 322.4, .cy = 236.8, .k1 = -0.28, .k2 = 0.09, .p1 = 0.001, .p2 = -0.0008})},
      {"atan_fov", Camera(640, 480, AtanCamera{.fx = 420, .fy = 421, .cx = 318.9, .cy = 241.3, .w = 0.92})},
  };
}

// A 1 m cube standing on the ground (z up) at the origin, turned so that a
// camera in front sees three faces.
VirtualObject test_cube() {
  VirtualObject cube;
  cube.size = 1.0;
  cube.T_w_o.linear() = Eigen::AngleAxisd(0.35, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  cube.T_w_o.translation() = Eigen::Vector3d(0.1, -0.05, 0.0);
  return cube;
}

// A camera looking at the cube's centre from `distance` along its body
// diagonal (three faces equally in view), turned `turn` radians off it.
Eigen::Isometry3d diagonal_view(const VirtualObject& cube, double distance, double turn) {
  const Eigen::Vector3d centre = cube.T_w_o * Eigen::Vector3d(0, 0, 0.5 * cube.size);
  const Eigen::Vector3d diagonal_o =
      Eigen::AngleAxisd(turn, Eigen::Vector3d::UnitZ()) * Eigen::Vector3d(-1, -1, 1).normalized();
  return test::look_at(centre + distance * (cube.T_w_o.linear() * diagonal_o), centre);
}

// A grey image: the corners' contrast must come from the object.
cv::Mat grey_image(const Camera& camera) {
  return cv::Mat(camera.height(), camera.width(), CV_8UC3, cv::Scalar::all(60));
}

struct CornerErrors {
  std::size_t corners = 0;
  double worst = 0.0, mean = 0.0;
};

// Finds, with cv::cornerSubPix, the object's checker corners (X-junctions)
// on the faces turned towards the camera, starting off the prediction;
// returns their distances from Camera::project(). (The cube's own corners
// are Y-junctions, where cornerSubPix is biased towards the inside by about
// the blur; the silhouette test below checks them.)
CornerErrors measure_object_corners(const cv::Mat& image, const Camera& camera, const Eigen::Isometry3d& T_w_c,
                                    const VirtualObject& object) {
  cv::Mat grey;
  cv::cvtColor(image, grey, cv::COLOR_BGR2GRAY);
  // As in marker_exactness_test: a symmetric blur smooths the staircase of
  // the edges and keeps the junctions where they are.
  cv::GaussianBlur(grey, grey, cv::Size(0, 0), 1.2);
  const Eigen::Isometry3d T_c_w = T_w_c.inverse();
  const Eigen::Vector3d eye = T_w_c.translation();
  std::vector<Eigen::Vector3d> targets;
  for (const VirtualObject::FacePoint& p : object.checker_corners_w()) {
    // Faces seen obliquely squeeze the squares to a few pixels: skip them.
    if (p.face_normal_w.dot((eye - p.p_w).normalized()) > 0.35) targets.push_back(p.p_w);
  }
  std::vector<cv::Point2f> predicted, found;
  for (const Eigen::Vector3d& p_w : targets) {
    const Eigen::Vector2d px = camera.project(T_c_w * p_w);
    EXPECT_TRUE(camera.in_image(px, 12.0)) << "a corner outside the image: fix the test pose";
    predicted.emplace_back(static_cast<float>(px.x()), static_cast<float>(px.y()));
    found.emplace_back(static_cast<float>(px.x() + 1.2), static_cast<float>(px.y() - 0.9));
  }
  cv::cornerSubPix(grey, found, cv::Size(5, 5), cv::Size(-1, -1),
                   cv::TermCriteria(cv::TermCriteria::EPS + cv::TermCriteria::COUNT, 200, 1e-5));
  CornerErrors errors;
  errors.corners = found.size();
  for (std::size_t i = 0; i < found.size(); ++i) {
    const double error = cv::norm(found[i] - predicted[i]);
    errors.worst = std::max(errors.worst, error);
    errors.mean += error / static_cast<double>(found.size());
  }
  return errors;
}

class ArViewExactness : public ::testing::TestWithParam<int> {};

TEST_P(ArViewExactness, ObjectCornersSitWhereTheCameraModelProjectsThem) {
  const CameraCase c = cameras()[GetParam()];
  ArView view(c.camera);
  ArFrameContent content;
  content.image = grey_image(c.camera);
  content.object = test_cube();
  const Eigen::Isometry3d T_w_c = diagonal_view(*content.object, 2.9, 0.15);
  content.T_w_c = T_w_c;
  render::ar::ArFrameStats stats;
  const cv::Mat image = view.render(content, &stats);
  EXPECT_TRUE(stats.object_drawn);
  const CornerErrors e = measure_object_corners(image, c.camera, T_w_c, *content.object);
  std::cout << "[ ar object ] " << c.name << ": " << e.corners << " corners, mean " << e.mean << " px, max " << e.worst
            << " px\n";
  RecordProperty("max_corner_error_px", std::to_string(e.worst));
  EXPECT_GE(e.corners, 30u);
  EXPECT_LT(e.worst, 0.5) << c.name;
}

TEST_P(ArViewExactness, PointsAreDrawnCentredOnTheirProjections) {
  const CameraCase c = cameras()[GetParam()];
  render::ar::ArViewStyle style;
  style.point_size = 5.f;
  ArView view(c.camera, style);
  ArFrameContent content;
  content.image = cv::Mat(c.camera.height(), c.camera.width(), CV_8UC3, cv::Scalar::all(0));
  const Eigen::Isometry3d T_w_c = test::look_at({-3.0, 0.2, 0.4}, {0, 0, 0}, Eigen::Vector3d::UnitZ(), 0.1);
  content.T_w_c = T_w_c;
  // A grid of points on a wall, spread over the whole image (the distortion
  // is strongest in the corners), at least ~20 px apart.
  std::vector<Eigen::Vector2d> predicted;
  for (int i = -9; i <= 9; ++i)
    for (int j = -7; j <= 7; ++j) {
      const Eigen::Vector3d p_w(0.0, 0.27 * i + 0.013 * j, 0.25 * j + 0.011 * i);
      const Eigen::Vector2d px = c.camera.project(T_w_c.inverse() * p_w);
      if (!c.camera.in_image(px, 6.0)) continue;
      content.points.push_back({p_w, cv::Vec3b(255, 255, 255)});
      predicted.push_back(px);
    }
  ASSERT_GT(predicted.size(), 100u);
  render::ar::ArFrameStats stats;
  const cv::Mat image = view.render(content, &stats);
  EXPECT_EQ(stats.points_drawn, predicted.size());
  cv::Mat mask, labels, blobs, centroids;
  cv::cvtColor(image, mask, cv::COLOR_BGR2GRAY);
  mask = mask > 0;
  const int count = cv::connectedComponentsWithStats(mask, labels, blobs, centroids, 8);
  ASSERT_EQ(static_cast<std::size_t>(count - 1), predicted.size()) << "dots merged or missing";
  double worst = 0.0;
  for (const Eigen::Vector2d& px : predicted) {
    double nearest = 1e9;
    for (int k = 1; k < count; ++k)
      nearest = std::min(nearest, std::hypot(centroids.at<double>(k, 0) - px.x(), centroids.at<double>(k, 1) - px.y()));
    worst = std::max(worst, nearest);
  }
  std::cout << "[ ar points ] " << c.name << ": " << predicted.size() << " points, max centre error " << worst
            << " px\n";
  RecordProperty("max_point_error_px", std::to_string(worst));
  EXPECT_LT(worst, 0.5) << c.name;
}

INSTANTIATE_TEST_SUITE_P(Cameras, ArViewExactness, ::testing::Range(0, 3),
                         [](const ::testing::TestParamInfo<int>& info) { return cameras()[info.param].name; });

// A synthetic sequence with ground truth: a camera walking past a patch of
// ground. The object is placed once, from the map points (ground samples)
// and the first pose, then every frame's render must show its corners where
// that frame's true pose projects the same world points.
TEST(ArViewAnchoring, TheObjectStaysPutAsTheCameraMoves) {
  const Camera camera(
      640, 480,
      PinholeRadTan{
          .fx = 480, .fy = 482, .cx = 322.4, .cy = 236.8, .k1 = -0.2, .k2 = 0.05, .p1 = 0.0005, .p2 = -0.0004});
  std::vector<Eigen::Vector3d> ground;
  for (int i = 0; i < 30; ++i)
    for (int j = 0; j < 30; ++j) ground.emplace_back(-3.0 + 0.2 * i, -3.0 + 0.2 * j, 0.0);
  std::vector<Eigen::Isometry3d> poses;
  for (int k = 0; k < 5; ++k) {
    const double a = -0.5 + 0.25 * k;  // the camera circles the anchor
    poses.push_back(test::look_at({-3.0 * std::cos(a), -3.0 * std::sin(a), 1.8}, {0, 0, 0.4}));
  }
  const auto fit = render::ar::find_dominant_plane(ground);
  ASSERT_TRUE(fit.has_value());
  render::ar::PlacementOptions placement;
  placement.size_fraction = 0.3;
  const auto object = render::ar::place_on_plane(*fit, ground, poses.front(), placement);
  ASSERT_TRUE(object.has_value());
  // It stands on the ground (its bottom face on z = 0), upright.
  for (int i = 0; i < 4; ++i) EXPECT_NEAR(object->corners_w()[i].z(), 0.0, 1e-9);
  EXPECT_GT(object->corners_w()[4].z(), 0.5);

  ArView view(camera);
  double worst = 0.0;
  for (const Eigen::Isometry3d& T_w_c : poses) {
    ArFrameContent content;
    content.image = grey_image(camera);
    content.object = object;
    content.T_w_c = T_w_c;
    const CornerErrors e = measure_object_corners(view.render(content), camera, T_w_c, *object);
    EXPECT_GE(e.corners, 10u);
    worst = std::max(worst, e.worst);
  }
  std::cout << "[ ar anchoring ] " << poses.size() << " frames, max corner error " << worst << " px\n";
  EXPECT_LT(worst, 0.5);
}

TEST(ArView, PointsBehindTheObjectAreNotDrawn) {
  const Camera camera = cameras()[0].camera;
  ArView view(camera);
  ArFrameContent content;
  content.image = grey_image(camera);
  content.object = test_cube();
  content.T_w_c = diagonal_view(*content.object, 2.9, 0.15);
  const Eigen::Vector3d eye = content.T_w_c->translation();
  const Eigen::Vector3d centre = content.object->T_w_o * Eigen::Vector3d(0, 0, 0.5);
  // On the line of sight through the cube's centre: before it, inside it,
  // just behind it, far behind it.
  for (const double t : {0.3, 1.0, 1.4, 2.5})
    content.points.push_back({eye + t * (centre - eye), cv::Vec3b(0, 0, 255)});
  // Beside the cube: seen.
  content.points.push_back({centre + 1.0 * content.T_w_c->linear().col(0), cv::Vec3b(0, 0, 255)});
  render::ar::ArFrameStats stats;
  view.render(content, &stats);
  EXPECT_EQ(stats.points_drawn, 2u);  // the one before it and the one beside it
  content.object.reset();
  view.render(content, &stats);
  EXPECT_EQ(stats.points_drawn, 5u);
}

TEST(ArView, AFrameWithoutPoseOrMapIsTheImageUntouched) {
  const Camera camera = cameras()[1].camera;
  ArView view(camera);
  // The OSMesa link check for this path: a null GL_RENDERER means every
  // image would come out black without an error (render/gl_functions.hpp).
  EXPECT_FALSE(view.gl_renderer().empty());
  cv::Mat image(camera.height(), camera.width(), CV_8UC3);
  cv::randu(image, cv::Scalar::all(0), cv::Scalar::all(256));

  ArFrameContent lost;  // no pose: points and object are not drawn
  lost.image = image;
  lost.object = test_cube();
  lost.points.push_back({Eigen::Vector3d(0, 0, 0.5), cv::Vec3b(0, 0, 255)});
  lost.legend.push_back({"level 0", cv::Vec3b(0, 0, 255), false});
  render::ar::ArFrameStats stats;
  cv::Mat out = view.render(lost, &stats);
  EXPECT_FALSE(stats.object_drawn);
  EXPECT_EQ(stats.points_drawn, 0u);
  EXPECT_EQ(cv::norm(out, image, cv::NORM_INF), 0.0);

  ArFrameContent empty_map;  // a pose, but nothing in the map yet
  empty_map.image = image;
  empty_map.T_w_c = test::look_at({-2.2, -1.6, 1.5}, {0, 0, 0.4});
  out = view.render(empty_map, &stats);
  EXPECT_FALSE(stats.object_drawn);
  EXPECT_EQ(cv::norm(out, image, cv::NORM_INF), 0.0);

  // A grey image is drawn as grey BGR.
  cv::Mat grey;
  cv::cvtColor(image, grey, cv::COLOR_BGR2GRAY);
  empty_map.image = grey;
  cv::Mat grey_bgr;
  cv::cvtColor(grey, grey_bgr, cv::COLOR_GRAY2BGR);
  EXPECT_EQ(cv::norm(view.render(empty_map), grey_bgr, cv::NORM_INF), 0.0);

  // Of another size: an error, not a stretched picture.
  empty_map.image = cv::Mat(10, 10, CV_8UC3, cv::Scalar::all(0));
  EXPECT_THROW(view.render(empty_map), Error);
}

// The silhouette, cube corners included: the object drawn flat white over
// black, so that a pixel's grey level is the object's coverage (alpha),
// thresholded at one half; the reference casts the ray of each pixel centre
// against the cube's faces on the CPU (Camera::unproject). Where the two
// disagree, the true outline must pass within half a pixel: a ray half a
// pixel away (in one of 8 directions) must see the other side.
TEST_P(ArViewExactness, TheSilhouetteIsWithinHalfAPixelOfTheRayCastOne) {
  const CameraCase c = cameras()[GetParam()];
  render::ar::ArViewStyle flat;
  flat.ambient = 1.0;
  flat.object_bgr = flat.checker_bgr = cv::Vec3b(255, 255, 255);
  ArView view(c.camera, flat);
  ArFrameContent content;
  content.image = cv::Mat(c.camera.height(), c.camera.width(), CV_8UC3, cv::Scalar::all(0));
  content.object = test_cube();
  content.T_w_c = diagonal_view(*content.object, 2.9, 0.15);
  cv::Mat grey;
  cv::cvtColor(view.render(content), grey, cv::COLOR_BGR2GRAY);

  const auto k = content.object->corners_w();
  const std::vector<test::ReferenceQuad> faces{
      {k[4], k[5] - k[4], k[7] - k[4], {}, 1}, {k[0], k[1] - k[0], k[3] - k[0], {}, 1},
      {k[0], k[1] - k[0], k[4] - k[0], {}, 1}, {k[1], k[2] - k[1], k[5] - k[1], {}, 1},
      {k[2], k[3] - k[2], k[6] - k[2], {}, 1}, {k[3], k[0] - k[3], k[7] - k[3], {}, 1}};
  const auto hit = [&](double x, double y) { return test::cast_ray(faces, c.camera, *content.T_w_c, x, y).quad >= 0; };
  // Rays are cast only inside the box around the projected edges (sampled
  // densely: distortion bends them) plus a margin; outside it nothing may be
  // drawn. (A whole-image ray cast takes seconds under the sanitizers.)
  double min_x = 1e9, min_y = 1e9, max_x = -1e9, max_y = -1e9;
  const int edges[12][2] = {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}, {5, 6},
                            {6, 7}, {7, 4}, {0, 4}, {1, 5}, {2, 6}, {3, 7}};
  for (const auto& e : edges)
    for (int i = 0; i <= 64; ++i) {
      const Eigen::Vector3d p_w = k[e[0]] + (i / 64.0) * (k[e[1]] - k[e[0]]);
      const Eigen::Vector2d px = c.camera.project(content.T_w_c->inverse() * p_w);
      min_x = std::min(min_x, px.x()), max_x = std::max(max_x, px.x());
      min_y = std::min(min_y, px.y()), max_y = std::max(max_y, px.y());
    }
  const cv::Rect search = cv::Rect(cv::Point(static_cast<int>(min_x) - 3, static_cast<int>(min_y) - 3),
                                   cv::Point(static_cast<int>(max_x) + 4, static_cast<int>(max_y) + 4)) &
                          cv::Rect(0, 0, c.camera.width(), c.camera.height());
  ASSERT_GT(search.area(), 10000);
  int covered = 0, disagreeing = 0, far_from_outline = 0;
  for (int y = 0; y < c.camera.height(); ++y)
    for (int x = 0; x < c.camera.width(); ++x) {
      const bool rendered = grey.at<std::uint8_t>(y, x) >= 128;
      const bool inside = search.contains(cv::Point(x, y));
      const bool reference = inside && hit(x, y);
      covered += rendered;
      if (rendered == reference) continue;
      ++disagreeing;
      if (!inside) {  // drawn where the cube cannot be
        ++far_from_outline;
        continue;
      }
      bool outline_near = false;
      for (int d = 0; d < 8 && !outline_near; ++d) {
        const double a = d * CV_PI / 4;
        outline_near = hit(x + 0.5 * std::cos(a), y + 0.5 * std::sin(a)) != reference;
      }
      far_from_outline += !outline_near;
    }
  std::cout << "[ ar silhouette ] " << c.name << ": " << covered << " pixels, " << disagreeing
            << " differ from the ray cast, " << far_from_outline << " of them more than 0.5 px from the outline\n";
  EXPECT_GT(covered, 10000);
  EXPECT_EQ(far_from_outline, 0) << c.name;
}

}  // namespace
}  // namespace facadeslam
